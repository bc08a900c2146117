// A jumble nobody tuned (scenes/hard/slope_jumble.json, drawn by tools/untuned-sweep): nine boxes
// of mixed size, density, friction and restitution dropped onto a slope. Criterion, both contact
// models, 3 s: no run-time fault (the run stops on one) and no overlap above 1 mm at any step. The
// time-stepping run once stopped at 0.98 s: a 197 kg box bounced two steps after the step that
// closed its gap, as the model allows (time_stepping/contact_impulses.h, kOwedBounceCarries), while
// the fault check expected every bounce within one.
#include <catch2/catch.hpp>

#include "../dynamics/contact_scene_runner.h"

using namespace tumble;

namespace {

// The deepest overlap of any step, m; a run-time fault stops the run and fails the test.
double deepestOverlap(ContactModel model) {
  return test::runScene("hard/slope_jumble", 3, {}, 1, [&](Scene& s) { s.simulation.step.model = model; })
      .max_penetration;
}

}  // namespace

TEST_CASE("boxes of mixed size, density and restitution dropped onto a slope: no fault, no overlap, Baraff",
          "[hard][slope_jumble]") {
  const double deepest = deepestOverlap(ContactModel::Baraff);
  INFO("deepest overlap " << deepest << " m");
  CHECK(deepest < 1e-3);
}

TEST_CASE("boxes of mixed size, density and restitution dropped onto a slope: no fault, time stepping",
          "[hard][slope_jumble][time_stepping]") {
  CHECK_NOTHROW(deepestOverlap(ContactModel::TimeStepping));
}

// Known failure: 1.25 mm for one step at 1.11 s (2026-11-27, since the drift projection pushes
// pairs apart at their points), the next step back under 0.2 mm: a box landing in the heap with a
// corner the start-of-step contacts did not hold (docs/known-limits.md, the time-stepping model is
// first order and sees contacts at the start of the step). Each change of the heap's path moves
// this figure: 1.65 mm before manifolds were kept between steps, 0.45 mm with them; the cause
// stays.
TEST_CASE("boxes of mixed size, density and restitution dropped onto a slope: no overlap above 1 mm, time stepping (reached: 1.25 mm)",
          "[hard][slope_jumble][time_stepping][!shouldfail]") {
  const double deepest = deepestOverlap(ContactModel::TimeStepping);
  INFO("deepest overlap " << deepest << " m");
  CHECK(deepest < 1e-3);
}
