// S5 free spin (Dzhanibekov): energy and |L| drift, flips of the body-frame omega_y, and the final
// orientation against a reference integration of Euler's equations (RK4, h = 1e-4 s).
#include <algorithm>
#include <cmath>
#include <map>

#include "bench/metrics.h"

namespace tumble::bench {
namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

Vector3d boxInertia(const BoxBody& b) {
  const Vector3d e = 2 * b.half_extents;   // full edges a, b, c
  return b.mass / 12 * Vector3d(e.y() * e.y() + e.z() * e.z(), e.x() * e.x() + e.z() * e.z(),
                                e.x() * e.x() + e.y() * e.y());
}

// Torque-free rigid body in body axes: I w' = (I w) x w, and q' = 1/2 q (0, w).
struct SpinState {
  Vector3d w;
  Quaterniond q;
};

SpinState derivative(const SpinState& s, const Vector3d& inertia) {
  SpinState d;
  d.w = (inertia.cwiseProduct(s.w)).cross(s.w).cwiseQuotient(inertia);
  const Quaterniond wq(0, s.w.x(), s.w.y(), s.w.z());
  d.q.coeffs() = 0.5 * (s.q * wq).coeffs();
  return d;
}

SpinState axpy(const SpinState& s, double h, const SpinState& d) {
  SpinState r;
  r.w = s.w + h * d.w;
  r.q.coeffs() = s.q.coeffs() + h * d.q.coeffs();
  return r;
}

struct Reference {
  Quaterniond q;
  int flips = 0;
};

// The reference up to time t_end (h = 1e-4 s, the last step shortened to land on t_end).
Reference referenceSpin(const BoxBody& body, double t_end) {
  static std::map<std::pair<double, double>, Reference> cache;   // one per (duration, I_y) asked
  const Vector3d inertia = boxInertia(body);
  const auto key = std::make_pair(t_end, inertia.y());
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  SpinState s{body.q.conjugate() * body.w, body.q};
  Reference ref;
  double t = 0, prev_wy = s.w.y();
  while (t < t_end - 1e-12) {
    const double h = std::min(1e-4, t_end - t);
    const SpinState k1 = derivative(s, inertia);
    const SpinState k2 = derivative(axpy(s, h / 2, k1), inertia);
    const SpinState k3 = derivative(axpy(s, h / 2, k2), inertia);
    const SpinState k4 = derivative(axpy(s, h, k3), inertia);
    s.w += h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w);
    s.q.coeffs() += h / 6 * (k1.q.coeffs() + 2 * k2.q.coeffs() + 2 * k3.q.coeffs() + k4.q.coeffs());
    s.q.normalize();
    t += h;
    if (s.w.y() * prev_wy < 0) ++ref.flips;
    if (s.w.y() != 0) prev_wy = s.w.y();
  }
  ref.q = s.q;
  return cache[key] = ref;
}

class FreeSpin : public MetricCollector {
 public:
  explicit FreeSpin(const BenchScene& scene) : body_(scene.bodies[0]), inertia_(boxInertia(body_)) {}

  void observe(const std::vector<BodyState>& s, int k, double t) override {
    const Vector3d wb = s[0].q.conjugate() * s[0].w;   // body-frame angular velocity
    const double energy = 0.5 * wb.dot(inertia_.cwiseProduct(wb));
    const double l = inertia_.cwiseProduct(wb).norm();   // |L| is frame independent
    if (k == 0) {
      e0_ = energy;
      l0_ = l;
      prev_wy_ = wb.y();
    }
    de_ = energy / e0_ - 1;
    dl_ = l / l0_ - 1;
    de_max_ = std::max(de_max_, std::abs(de_));
    dl_max_ = std::max(dl_max_, std::abs(dl_));
    if (wb.y() * prev_wy_ < 0) ++flips_;
    if (wb.y() != 0) prev_wy_ = wb.y();
    q_ = s[0].q;
    t_ = t;
  }

  std::vector<Metric> finish() override {
    const Reference ref = referenceSpin(body_, t_);
    const double cos_half = std::min(1.0, std::abs(q_.dot(ref.q)));
    return {{"dE_max", de_max_},         {"dL_max", dl_max_},
            {"dE_final", de_},           {"dL_final", dl_},
            {"wy_sign_flips", static_cast<double>(flips_)},
            {"ref_flips", static_cast<double>(ref.flips)},
            {"orient_err_deg", 2 * std::acos(cos_half) * 180 / M_PI}};
  }

 private:
  BoxBody body_;
  Vector3d inertia_;
  double e0_ = 0, l0_ = 0, de_ = 0, dl_ = 0, de_max_ = 0, dl_max_ = 0, prev_wy_ = 0, t_ = 0;
  int flips_ = 0;
  Quaterniond q_ = Quaterniond::Identity();
};

}  // namespace

std::unique_ptr<MetricCollector> makeFreeSpinCollector(const BenchScene& scene, double) {
  return std::make_unique<FreeSpin>(scene);
}

}  // namespace tumble::bench
