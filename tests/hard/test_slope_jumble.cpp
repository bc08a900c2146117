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

// 0.45 mm (2026-11-27, with manifolds kept between steps). It was a known failure before, 1.65 mm
// for a step: a box landing in the heap with a corner the start-of-step contacts did not hold.
// Keeping manifolds changed the heap's path, not that cause (docs/known-limits.md, the
// time-stepping model is first order and sees contacts at the start of the step): another heap
// may land a corner as deep.
TEST_CASE("boxes of mixed size, density and restitution dropped onto a slope: no overlap above 1 mm, time stepping",
          "[hard][slope_jumble][time_stepping]") {
  const double deepest = deepestOverlap(ContactModel::TimeStepping);
  INFO("deepest overlap " << deepest << " m");
  CHECK(deepest < 1e-3);
}
