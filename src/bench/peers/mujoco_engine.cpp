// MuJoCo 2.2.2 as docs/bench/peers.md sets it up: MJCF generated per scene (mjcf_writer.cpp), the
// defaults otherwise (semi-implicit Euler, Newton solver with 100 iterations and tol 1e-8,
// pyramidal cones), restitution emulated by an under-damped contact. mujoco-cg is the CG solver
// the peers used for the piles.
#include <mujoco/mujoco.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "bench/engine.h"
#include "bench/peers/mjcf_writer.h"

namespace tumble::bench {
namespace {

// MuJoCo prints each kind of warning once; the counts in mjData say how often it happened.
void quietWarning(const char*) {}

mjModel* loadModel(const std::string& xml) {
  // 2.2.2 loads MJCF from a file name: write it to a private temporary file.
  std::string path = (std::filesystem::temp_directory_path() / "tumble-bench-XXXXXX.xml").string();
  const int fd = mkstemps(path.data(), 4);
  if (fd < 0) throw std::runtime_error("cannot create a temporary MJCF file");
  close(fd);
  std::ofstream(path) << xml;
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(path);
  if (!m) throw std::runtime_error(std::string("MuJoCo rejected the model: ") + error);
  return m;
}

class MujocoEngine : public Engine {
 public:
  MujocoEngine(const BenchScene& scene, double dt, const MujocoOptions& opt)
      : m_(loadModel(mjcfOf(scene, dt, opt))), d_(mj_makeData(m_)), n_(scene.bodies.size()) {
    mju_user_warning = quietWarning;
    for (std::size_t i = 0; i < n_; ++i) {
      const BoxBody& b = scene.bodies[i];
      mjtNum* v = d_->qvel + m_->jnt_dofadr[i];
      // A free joint's angular velocity is in the body frame.
      const Eigen::Vector3d w_body = b.q.conjugate() * b.w;
      for (int k = 0; k < 3; ++k) {
        v[k] = b.v[k];
        v[3 + k] = w_body[k];
      }
    }
  }
  ~MujocoEngine() override {
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }

  void step() override { mj_step(m_, d_); }

  void read(std::vector<BodyState>& out) const override {
    out.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const mjtNum* q = d_->qpos + m_->jnt_qposadr[i];
      const mjtNum* v = d_->qvel + m_->jnt_dofadr[i];
      const Eigen::Quaterniond rot(q[3], q[4], q[5], q[6]);
      out[i] = {{q[0], q[1], q[2]}, rot, {v[0], v[1], v[2]}, rot * Eigen::Vector3d(v[3], v[4], v[5])};
    }
  }

  std::string note() const override {
    std::string s;
    const int full = d_->warning[mjWARN_CONTACTFULL].number, efc = d_->warning[mjWARN_CNSTRFULL].number;
    if (full) s += "contact list full " + std::to_string(full) + "x (contacts dropped: INVALID) ";
    if (efc) s += "constraint rows full " + std::to_string(efc) + "x (INVALID) ";
    return s;
  }

 private:
  mjModel* m_;
  mjData* d_;
  std::size_t n_;
};

EngineSetting mujocoSetting(const std::string& name, MujocoOptions opt) {
  EngineSetting s = settingOf<MujocoEngine>(name, "mujoco", opt);
  s.skip_reason = [opt](const BenchScene& scene) {
    if (scene.ccd) return std::string("MuJoCo has no continuous collision detection");
    if (opt.cg && scene.kind != SceneKind::Pile) return std::string("CG is the piles' setting");
    if (!opt.cg && scene.kind == SceneKind::Pile && scene.bodies.size() >= 1000)
      return std::string("2.2.2 Newton: dense 6000 x 6000 Hessian and a contact buffer too small (peers.md)");
    return std::string();
  };
  return s;
}

}  // namespace

// The library's own version string ("2.2.2"), not the header's.
std::string mujocoVersion() { return mj_versionString(); }

std::vector<EngineSetting> mujocoSettings() {
  return {mujocoSetting("mujoco", {false}), mujocoSetting("mujoco-cg", {true})};
}

}  // namespace tumble::bench
