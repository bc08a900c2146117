// Collectors of the small contact scenes: S1 cube drop, S2 incline, S3 rest, S4 stack, S7 mass
// ratio, S8 tunnelling (definitions: docs/bench/scenes.md).
#include <algorithm>
#include <cmath>

#include "bench/metrics.h"

namespace tumble::bench {
namespace {

// S1. The impact is the first step in which v_z increases (its midpoint, (k - 1/2) dt); the apex
// is the highest centre between the impact and the first sample with v_z <= 0 after v_z has
// exceeded 0.05 m/s.
class CubeDrop : public MetricCollector {
 public:
  explicit CubeDrop(double dt) : dt_(dt) {}
  void observe(const std::vector<BodyState>& s, int k, double) override {
    const BodyState& b = s[0];
    max_w_ = std::max(max_w_, b.w.norm());
    const double vz = b.v.z();
    if (k > 0 && t_impact_ < 0 && vz > prev_vz_) t_impact_ = (k - 0.5) * dt_;
    prev_vz_ = vz;
    if (t_impact_ < 0 || window_closed_) return;
    apex_ = std::max(apex_, b.x.z());
    if (vz > 0.05) rising_ = true;
    if (rising_ && vz <= 0) window_closed_ = true;
  }
  std::vector<Metric> finish() override {
    const double analytic_t = std::sqrt(2 * 1.0 / 9.81);
    const double e_eff = std::sqrt(std::max(0.0, apex_ - 0.5));
    const double nan = std::nan("");
    return {{"t_impact_err", t_impact_ < 0 ? nan : t_impact_ - analytic_t},
            {"apex", t_impact_ < 0 ? nan : apex_},
            {"apex_err", t_impact_ < 0 ? nan : std::abs(apex_ - 0.75)},
            {"e_eff", e_eff},
            {"max_w", max_w_}};
  }

 private:
  double dt_, prev_vz_ = 0, t_impact_ = -1, apex_ = -1e300, max_w_ = 0;
  bool rising_ = false, window_closed_ = false;
};

// S2. Displacement down the slope (-x); the analytic slide is 1/2 g (sin30 - mu cos30) t^2, taken
// at the time actually reached so that a shortened run is still judged fairly.
class Incline : public MetricCollector {
 public:
  Incline(bool sliding, double mu) : sliding_(sliding), mu_(mu) {}
  void observe(const std::vector<BodyState>& s, int, double t) override {
    max_w_ = std::max(max_w_, s[0].w.norm());
    disp_ = -s[0].x.x();
    t_ = t;
  }
  std::vector<Metric> finish() override {
    if (!sliding_) return {{"disp", disp_}, {"creep", std::abs(disp_)}, {"max_w", max_w_}};
    const double a = 9.81 * (std::sin(M_PI / 6) - mu_ * std::cos(M_PI / 6));
    return {{"disp", disp_}, {"abs_err", std::abs(disp_ - 0.5 * a * t_ * t_)}, {"max_w", max_w_}};
  }

 private:
  bool sliding_;
  double mu_, disp_ = 0, t_ = 0, max_w_ = 0;
};

// S3. A cube resting on the ground should not move at all.
class Rest : public MetricCollector {
 public:
  explicit Rest(const BenchScene& scene) : scene_(scene) {}
  void observe(const std::vector<BodyState>& s, int, double t) override {
    max_pen_ = std::max(max_pen_, scenePenetration(scene_, s));
    if (t >= 1.0) {
      jitter_v_ = std::max(jitter_v_, s[0].v.norm());
      jitter_w_ = std::max(jitter_w_, s[0].w.norm());
    }
    last_ = s[0];
  }
  std::vector<Metric> finish() override {
    return {{"max_pen", max_pen_},
            {"drift_xy", last_.x.head<2>().norm()},
            {"sink", 0.5 - last_.x.z()},
            {"jitter_v", jitter_v_},
            {"jitter_w", jitter_w_}};
  }

 private:
  const BenchScene& scene_;
  double max_pen_ = 0, jitter_v_ = 0, jitter_w_ = 0;
  BodyState last_{};
};

// S4 and S7: a tower that must keep standing; the top box is the last body.
class Tower : public MetricCollector {
 public:
  Tower(const BenchScene& scene, double top_z0) : scene_(scene), top_z0_(top_z0) {}
  void observe(const std::vector<BodyState>& s, int, double) override {
    max_pen_ = std::max(max_pen_, scenePenetration(scene_, s));
    top_ = s.back();
  }
  std::vector<Metric> finish() override {
    const double dz = top_.x.z() - top_z0_;
    return {{"max_pen", max_pen_},
            {"top_drift_xy", top_.x.head<2>().norm()},
            {"top_dz", dz},
            {"standing", std::abs(dz) < 0.05 ? 1.0 : 0.0}};
  }

 private:
  const BenchScene& scene_;
  double top_z0_, max_pen_ = 0;
  BodyState top_{};
};

// S8: the share of cubes that end completely beyond the 1 cm wall (centre x > 5.06).
class Tunnel : public MetricCollector {
 public:
  void observe(const std::vector<BodyState>& s, int, double) override { last_ = s; }
  bool needsEveryStep() const override { return false; }
  std::vector<Metric> finish() override {
    const auto passed = std::count_if(last_.begin(), last_.end(),
                                      [](const BodyState& b) { return b.x.x() > 5.06; });
    return {{"passed_frac", static_cast<double>(passed) / static_cast<double>(last_.size())}};
  }

 private:
  std::vector<BodyState> last_;
};

}  // namespace

std::unique_ptr<MetricCollector> makeFreeSpinCollector(const BenchScene& scene, double dt);
std::unique_ptr<MetricCollector> makePileCollector(const BenchScene& scene);

std::unique_ptr<MetricCollector> makeCollector(const BenchScene& scene, double dt) {
  switch (scene.kind) {
    case SceneKind::CubeDrop: return std::make_unique<CubeDrop>(dt);
    case SceneKind::InclineSlide: return std::make_unique<Incline>(true, scene.friction);
    case SceneKind::InclineStick: return std::make_unique<Incline>(false, scene.friction);
    case SceneKind::Rest: return std::make_unique<Rest>(scene);
    case SceneKind::Stack: return std::make_unique<Tower>(scene, 9.5);
    case SceneKind::MassRatio: return std::make_unique<Tower>(scene, 1.5);
    case SceneKind::FreeSpin: return makeFreeSpinCollector(scene, dt);
    case SceneKind::Pile: return makePileCollector(scene);
    case SceneKind::Tunnel: return std::make_unique<Tunnel>();
  }
  return nullptr;
}

std::string headlineMetric(SceneKind kind) {
  switch (kind) {
    case SceneKind::CubeDrop: return "apex_err";
    case SceneKind::InclineSlide: return "abs_err";
    case SceneKind::InclineStick: return "creep";
    case SceneKind::Rest: return "max_pen";
    case SceneKind::Stack: return "max_pen";
    case SceneKind::FreeSpin: return "dE_max";
    case SceneKind::Pile: return "sc_err";
    case SceneKind::MassRatio: return "max_pen";
    case SceneKind::Tunnel: return "passed_frac";
  }
  return "";
}

std::string headlineAxisTitle(SceneKind kind) {
  switch (kind) {
    case SceneKind::CubeDrop: return "apex_err = |apex − 0.75 m| (m)";
    case SceneKind::InclineSlide: return "abs_err = |slide − ½at²| (m)";
    case SceneKind::InclineStick: return "creep: displacement down the slope (m)";
    case SceneKind::Rest:
    case SceneKind::Stack:
    case SceneKind::MassRatio: return "max_pen: deepest penetration over the run (m)";
    case SceneKind::FreeSpin: return "dE_max = max |E/E₀ − 1| (relative)";
    case SceneKind::Pile: return "sc_err: RMS distance to the run at dt/4 (m)";
    case SceneKind::Tunnel: return "passed_frac: share of cubes through the wall (fraction)";
  }
  return "";
}

BoxPose poseOf(const BoxBody& box, const BodyState& s) {
  return {box.half_extents, s.x, s.q.toRotationMatrix()};
}

double scenePenetration(const BenchScene& scene, const std::vector<BodyState>& s) {
  std::vector<BoxPose> poses;
  poses.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) poses.push_back(poseOf(scene.bodies[i], s[i]));
  std::vector<BoxPose> walls;
  for (const BoxBody& w : scene.walls) walls.push_back({w.half_extents, w.x, w.q.toRotationMatrix()});
  double deepest = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (scene.ground) deepest = std::max(deepest, groundDepth(poses[i]));
    for (const BoxPose& w : walls) deepest = std::max(deepest, boxOverlap(poses[i], w));
    for (std::size_t j = i + 1; j < poses.size(); ++j)
      deepest = std::max(deepest, boxOverlap(poses[i], poses[j]));
  }
  return deepest;
}

}  // namespace tumble::bench
