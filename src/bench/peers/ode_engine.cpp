// ODE 0.16 (double precision) as docs/bench/peers.md sets it up: world ERP 0.2 and CFM 1e-5 (the
// defaults), a hash space, up to 8 contacts per geom pair from dCollide, dContactApprox1 so that
// mu is a coefficient (not a force limit in newtons), dContactBounce with bounce_vel 0.1 m/s when
// e > 0. ode-step = dWorldStep (Dantzig LCP), ode-quick = dWorldQuickStep (20 SOR iterations,
// w = 1.3, the defaults). Gyroscopic mode and auto-disable stay at their defaults (on, off).
#include <ode/ode.h>

#include <atomic>
#include <cstdarg>
#include <mutex>
#include <string>

#include "bench/engine.h"

namespace tumble::bench {
namespace {

constexpr int kMaxContacts = 8;

// ODE reports LCP trouble ("LCP internal error, s <= 0") through its message handler; count the
// messages instead of flooding the report, and say how many in the note.
std::atomic<long> g_ode_messages{0};
void countMessage(int, const char*, va_list) { ++g_ode_messages; }

void initOdeOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(countMessage);
  });
}

class OdeEngine : public Engine {
 public:
  OdeEngine(const BenchScene& scene, double dt, bool quick) : dt_(dt), quick_(quick) {
    initOdeOnce();
    messages_at_start_ = g_ode_messages;
    world_ = dWorldCreate();
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    dWorldSetGravity(world_, scene.gravity.x(), scene.gravity.y(), scene.gravity.z());
    mu_ = scene.friction;
    e_ = scene.restitution;
    if (scene.ground) dCreatePlane(space_, 0, 0, 1, 0);
    for (const BoxBody& w : scene.walls) place(boxGeom(w), w);
    for (const BoxBody& b : scene.bodies) {
      dBodyID body = dBodyCreate(world_);
      dMass m;
      const Eigen::Vector3d e = 2 * b.half_extents;
      dMassSetBoxTotal(&m, b.mass, e.x(), e.y(), e.z());
      dBodySetMass(body, &m);
      dBodySetPosition(body, b.x.x(), b.x.y(), b.x.z());
      const dQuaternion q{b.q.w(), b.q.x(), b.q.y(), b.q.z()};
      dBodySetQuaternion(body, q);
      dBodySetLinearVel(body, b.v.x(), b.v.y(), b.v.z());
      dBodySetAngularVel(body, b.w.x(), b.w.y(), b.w.z());
      dGeomSetBody(boxGeom(b), body);
      bodies_.push_back(body);
    }
  }

  ~OdeEngine() override {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);   // destroys its geoms
    dWorldDestroy(world_);   // and its bodies
  }

  void step() override {
    dSpaceCollide(space_, this, &OdeEngine::nearCallback);
    if (quick_) dWorldQuickStep(world_, dt_);
    else dWorldStep(world_, dt_);
    dJointGroupEmpty(contacts_);
  }

  void read(std::vector<BodyState>& out) const override {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const dReal* x = dBodyGetPosition(bodies_[i]);
      const dReal* q = dBodyGetQuaternion(bodies_[i]);
      const dReal* v = dBodyGetLinearVel(bodies_[i]);
      const dReal* w = dBodyGetAngularVel(bodies_[i]);
      out[i] = {{x[0], x[1], x[2]}, Eigen::Quaterniond(q[0], q[1], q[2], q[3]), {v[0], v[1], v[2]}, {w[0], w[1], w[2]}};
    }
  }

  std::string note() const override {
    const long n = g_ode_messages - messages_at_start_;
    return n ? std::to_string(n) + " ODE messages (LCP errors)" : "";
  }

 private:
  dGeomID boxGeom(const BoxBody& b) {
    const Eigen::Vector3d e = 2 * b.half_extents;
    return dCreateBox(space_, e.x(), e.y(), e.z());
  }

  static void place(dGeomID g, const BoxBody& b) {
    dGeomSetPosition(g, b.x.x(), b.x.y(), b.x.z());
    const dQuaternion q{b.q.w(), b.q.x(), b.q.y(), b.q.z()};
    dGeomSetQuaternion(g, q);
  }

  static void nearCallback(void* self, dGeomID a, dGeomID b) {
    static_cast<OdeEngine*>(self)->collide(a, b);
  }

  void collide(dGeomID a, dGeomID b) {
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (!ba && !bb) return;   // static against static
    dContact c[kMaxContacts];
    const int n = dCollide(a, b, kMaxContacts, &c[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      c[i].surface.mode = dContactApprox1 | (e_ > 0 ? dContactBounce : 0);
      c[i].surface.mu = mu_;
      c[i].surface.bounce = e_;
      c[i].surface.bounce_vel = 0.1;
      dJointAttach(dJointCreateContact(world_, contacts_, &c[i]), ba, bb);
    }
  }

  double dt_;
  bool quick_;
  double mu_ = 0.5, e_ = 0;
  long messages_at_start_ = 0;
  dWorldID world_;
  dSpaceID space_;
  dJointGroupID contacts_;
  std::vector<dBodyID> bodies_;
};

EngineSetting odeSetting(const std::string& name, bool quick) {
  EngineSetting s = settingOf<OdeEngine>(name, "ode", quick);
  s.skip_reason = [quick](const BenchScene& scene) {
    if (scene.ccd) return std::string("ODE has no continuous collision detection");
    // As in docs/bench/peers.md: the dense Dantzig LCP took 14 s per simulated s at N = 100.
    if (!quick && scene.kind == SceneKind::Pile && scene.bodies.size() >= 300)
      return std::string("dWorldStep (dense Dantzig LCP) far too slow at N >= 300");
    return std::string();
  };
  return s;
}

}  // namespace

// ODE has no version call; pkg-config's version of the package it was built against.
std::string odeVersion() { return TUMBLE_BENCH_ODE_VERSION; }

std::vector<EngineSetting> odeSettings() {
  return {odeSetting("ode-quick", true), odeSetting("ode-step", false)};
}

}  // namespace tumble::bench
