// S6 pile: everything is measured on the final state (penetration, boxes that escaped the bin);
// the self-consistency error (sc_err) is added by the runner, which owns the reference run.
#include <algorithm>
#include <cmath>

#include "bench/metrics.h"

namespace tumble::bench {
namespace {

class Pile : public MetricCollector {
 public:
  explicit Pile(const BenchScene& scene) : scene_(scene) {}
  bool needsEveryStep() const override { return false; }
  void observe(const std::vector<BodyState>& s, int, double) override { last_ = s; }

  std::vector<Metric> finish() override {
    int escaped = 0, below = 0, outside = 0;
    const double half = scene_.bin_half_m;
    for (const BodyState& b : last_) {
      const double reach = std::max(std::abs(b.x.x()), std::abs(b.x.y()));
      if (reach > half || b.x.z() < 0) ++escaped;       // centre left the interior [-half, half]^2
      if (b.x.z() < 0) ++below;                         // fell through the floor
      if (reach > half + 0.5) ++outside;                // beyond a wall's outer face
    }
    return {{"max_pen_end", scenePenetration(scene_, last_)},
            {"escaped", static_cast<double>(escaped)},
            {"below_floor", static_cast<double>(below)},
            {"outside_walls", static_cast<double>(outside)}};
  }

 private:
  const BenchScene& scene_;
  std::vector<BodyState> last_;
};

}  // namespace

std::unique_ptr<MetricCollector> makePileCollector(const BenchScene& scene) {
  return std::make_unique<Pile>(scene);
}

}  // namespace tumble::bench
