// Hard case 2 (docs/hard-cases.md): Newton's cradle. The impulse solver must pass an impact on
// through a chain of contacts (impulse_propagation.h) while still solving the points of one pair
// together, which the flat cube drop pins (tests/dynamics: no spin at all when it lands on four
// corners).
#include <catch2/catch.hpp>

#include <cmath>

#include "hard_run.h"

using namespace tumble;

namespace {

struct CradleOutcome {
  std::vector<double> vx;           // m/s, final x velocity of each ball
  double momentum_error = 0;        // relative, worst over the run
  double energy_error = 0;          // relative, worst over the run
  double max_spin = 0;              // rad/s
  std::vector<double> impact_times;
};

CradleOutcome runCradle(const std::string& scene_name) {
  Scene scene = hard::loadHardScene(scene_name);
  CradleOutcome out;
  const double p0 = 1.0, e0 = 0.5;   // 1 kg at 1 m/s
  hard::HardRun run = hard::simulate(scene, 0.2, [&](const World& w) {
    out.momentum_error = std::max(out.momentum_error, (hard::linearMomentum(w) - Eigen::Vector3d(p0, 0, 0)).norm() / p0);
    out.energy_error = std::max(out.energy_error, std::abs(hard::kineticEnergy(w) - e0) / e0);
    for (const RigidBody& b : w.bodies) out.max_spin = std::max(out.max_spin, b.angularVelocity().norm());
    return true;
  });
  for (const RigidBody& b : run.world.bodies) out.vx.push_back(b.velocity().x());
  out.impact_times = run.counters.impact_times;
  return out;
}

void checkCradle(const CradleOutcome& out) {
  INFO("final vx: " << out.vx[0] << " " << out.vx[1] << " " << out.vx[2] << " " << out.vx[3] << " " << out.vx[4]);
  REQUIRE(out.vx.size() == 5);
  // The physical answer; a simultaneous solve gives [-0.6, 0.4, 0.4, 0.4, 0.4].
  CHECK(out.vx[4] >= 0.99);
  for (int i = 0; i < 4; ++i) CHECK(std::abs(out.vx[i]) <= 0.01);
  CHECK(out.momentum_error < 1e-9);
  CHECK(out.energy_error < 1e-9);
  CHECK(out.max_spin < 1e-9);   // face-to-face impacts through the centres: no spin
}

}  // namespace

TEST_CASE("cradle: touching balls pass the impact on and only the last one leaves", "[hard][cradle]") {
  checkCradle(runCradle("cradle"));
}

TEST_CASE("cradle with 1e-6 m gaps: back-stepping finds four impacts, same answer", "[hard][cradle]") {
  CradleOutcome out = runCradle("cradle_gap");
  checkCradle(out);
  // Four separate impacts, in order, each after the previous ball has crossed its 1e-6 m gap at
  // 1 m/s (1e-6 s; the contact tolerance there is 1e-7 m, so 1e-7 s of slack either way).
  REQUIRE(out.impact_times.size() == 4);
  for (int k = 1; k < 4; ++k) {
    double gap_time = out.impact_times[k] - out.impact_times[k - 1];
    INFO("impact " << k << " after " << gap_time << " s");
    CHECK(std::abs(gap_time - 1e-6) < 3e-7);
  }
}
