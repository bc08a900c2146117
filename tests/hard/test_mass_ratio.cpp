// Hard case 4 (issue 6): a heavy cube resting on a light one, mass ratios 1 to 10000, 10 s.
#include <catch2/catch.hpp>

#include "../dynamics/contact_scene_runner.h"
#include "hard_run.h"

using namespace tumble;

namespace {

void checkStack(double ratio) {
  Scene scene = hard::loadHardScene("mass_ratio_sweep");
  scene.bodies[2].mass_kg = ratio;
  double max_pen = 0, max_drift = 0, light_energy = 0;
  const Eigen::Vector3d light0(0, 0, 0.5), heavy0(0, 0, 1.5);
  hard::simulate(scene, 10, [&](const World& w) {
    max_pen = std::max(max_pen, test::worldPenetration(w));
    max_drift = std::max({max_drift, (w.bodies[1].x - light0).norm(), (w.bodies[2].x - heavy0).norm()});
    if (w.time >= 1) light_energy = std::max(light_energy, w.bodies[1].kineticEnergy());
    return true;
  });
  INFO("ratio " << ratio << ": penetration " << max_pen << " m, drift " << max_drift
                << " m, light cube energy " << light_energy << " J");
  CHECK(max_pen < 1e-4);           // 1e-4 of the 1 m edge
  CHECK(max_drift < 1e-3);         // 1e-3 of the edge
  CHECK(light_energy < 1e-6);      // neither ejected nor jittering after 1 s
}

}  // namespace

TEST_CASE("mass ratio sweep: a heavy cube on a light one neither sinks, drifts nor jitters", "[hard][mass_ratio]") {
  checkStack(GENERATE(1.0, 10.0, 100.0, 1000.0));
}

// Known failure at 10000:1: the resting-force LCP leaves the light cube squeezed between the
// ground and a 10^4 times heavier body with a residual velocity of 2e-7 m/s (and 8e-7 rad/s) from
// the first step; the position projection then feeds it, and by 1.4 s the stack comes apart
// (drift 6.8 m, penetration 2.6 m at 10 s). Ratios up to 1000 pass with margin.
TEST_CASE("mass ratio 10000:1 stays stacked (reached: comes apart after 1.4 s)", "[hard][mass_ratio][!shouldfail]") {
  checkStack(10000.0);
}
