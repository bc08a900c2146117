// A frictionless 1000:1 stack (scenes/hard/frictionless_stack.json): a 10 m cube of 10^6 kg lands
// on a 1 m cube of 10^3 kg standing on the ground, with no friction anywhere. Nothing pushes either
// cube sideways, so after the landing both stay where they settled; a solver that lets the heavy
// cube's tilt (inside the contact tolerance) lean on the light one pushes it out sideways, with
// nothing to hold it back. Criterion: over 10 s both centres stay within 1 cm of where they were
// 1 s after the drop (the landing is over by then: the drop takes 0.32 s), no overlap above 1 mm,
// no run-time fault (the run stops on one).
#include <catch2/catch.hpp>

#include <cmath>

#include "../dynamics/contact_scene_runner.h"
#include "hard_run.h"

using namespace tumble;

namespace {

// The largest distance (m) either cube's centre moves from where it was at 1 s.
double drift(ContactModel model, double* penetration) {
  Eigen::Vector3d settled[2];
  bool have = false;
  double worst = 0;
  auto run = test::runScene("hard/frictionless_stack", 10, [&](const World& w) {
    if (w.time < 1 - 1e-9) return;
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d x = w.bodies[static_cast<std::size_t>(k + 1)].x;
      if (!have) settled[k] = x;
      worst = std::max(worst, (x - settled[k]).norm());
    }
    have = true;
  }, 1, [&](Scene& s) { s.simulation.step.model = model; });
  *penetration = run.max_penetration;
  return worst;
}

void checkStaysStacked(ContactModel model) {
  double penetration = 0;
  const double d = drift(model, &penetration);
  INFO("largest drift " << d << " m, deepest overlap " << penetration << " m");
  CHECK(d < 0.01);
  CHECK(penetration < 1e-3);
}

}  // namespace

// Time stepping: 3.2 mm of drift, overlaps of 1e-8 m (2026-11-24). It was a known failure,
// 1.1 cm, until islands that Gauss-Seidel leaves unconverged took subspace steps
// (active_set_step.h): a heavy body on a light one slows Gauss-Seidel by the mass ratio, and the
// residual it left pushed the light cube sideways at a steady 1.7e-4 m/s per second.
TEST_CASE("frictionless 1000:1 stack, time stepping: both cubes stay within 1 cm for 10 s",
          "[hard][frictionless_stack][time_stepping]") {
  checkStaysStacked(ContactModel::TimeStepping);
}

// Known failure (measured 2026-11-24): no overlap above 1.6e-6 m and no fault, but a kick to
// 1e-2 m/s between 1.3 s and 3.3 s, then a slow drift (1.8 cm). The cause is not found yet.
TEST_CASE("frictionless 1000:1 stack, Baraff: both cubes stay within 1 cm for 10 s (reached: 1.8 cm)",
          "[hard][frictionless_stack][!shouldfail]") {
  checkStaysStacked(ContactModel::Baraff);
}
