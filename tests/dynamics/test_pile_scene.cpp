// The pile (scenes/pile.json): 100 boxes and convex hulls dropped into a bin must, after
// 5 s, all rest inside it without penetrating more than 1e-3 m and without a numerical fault (a
// NaN, runaway energy or deep penetration stops the run with an error, failing the test).
//
// The full 5 s take about 10 minutes of wall time here (the settling pile is the slowest part: 115
// s per simulated s over the whole run), too long for the suite, so the suite runs the first
// second (the fall and the first impacts, about 10 s) and the 5 s test is hidden: run it with
// `build/tests/dynamics/test_contact_scenes "pile: after 5 s*"`.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "contact_scene_runner.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

// The bin of scenes/pile.json: walls 0.2 m thick centred at +-2.5 m, so the inside is |x|, |y| < 2.4.
constexpr double kInside = 2.4;

struct PileOutcome {
  double penetration = 0, speed = 0, spin = 0;   // deepest seen; largest at the end
  int outside = 0;                               // moving pieces outside the bin at the end
};

PileOutcome runPile(double seconds, const std::function<void(Scene&)>& edit = {}) {
  // Penetration by SAT over all pairs every 30 steps (8 frames of the 30 fps scene) and at the end.
  // These cases pin the Baraff model on the pile (the default, auto, runs a pile by time stepping:
  // the last case below).
  test::SceneRun run = test::runScene("pile", seconds, {}, 30, [&](Scene& s) {
    s.simulation.step.model = ContactModel::Baraff;
    if (edit) edit(s);
  });
  World start = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/pile.json")).world;
  const std::vector<BodySample>& end = run.trajectory.frames.back();
  REQUIRE(end.size() == start.bodies.size());
  PileOutcome out;
  out.penetration = run.max_penetration;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (start.bodies[i].is_static) continue;   // the ground and the walls
    const BodySample& b = end[i];
    out.speed = std::max(out.speed, b.v.norm());
    out.spin = std::max(out.spin, b.w.norm());
    if (std::abs(b.x.x()) > kInside || std::abs(b.x.y()) > kInside || b.x.z() < 0) ++out.outside;
  }
  INFO("largest speed at the end " << out.speed << " m/s, spin " << out.spin << " rad/s; outside the bin "
       << out.outside << "; deepest penetration " << out.penetration << " m");
  CHECK(out.outside == 0);
  return out;
}

}  // namespace

TEST_CASE("pile, Baraff: the first second falls into the bin without a numerical fault", "[contact][pile]") {
  runPile(1);
}

// Sampled every 30 steps. Before 48221f4 (2026-11-23) pairs ended steps overlapping by 2-8 mm
// during the first impacts (1.1 mm at these samples): a corner landing in a pair that already
// touched was not back-stepped, and the projection pushed each pair out by its deepest point,
// lifting its resting points too. With landings timed and the projection turning bodies about
// their resting points (position_projection.h), at 48221f4: 1.8e-4 m.
TEST_CASE("pile, Baraff: no penetration above 1e-3 m in the first second", "[contact][pile]") {
  CHECK(runPile(1).penetration < 1e-3);
}

// After 5 s every piece rests inside the bin. Hidden ([.]) for their cost, about a minute or two
// each: build/tests/dynamics/test_contact_scenes '[pile]'. At 065c393 (2026-11-28): the fastest
// piece at 3.4e-5 m/s and 3.0e-6 rad/s, no pair deeper than 1.0e-6 m at the samples.
//
// These three were known failures until 2026-11-28, the pile creeping at 0.078 m/s and 0.28 rad/s
// at 5 s (bdff5fc). Counted over 3.5-4.2 s then, 367 of 400 kicks to settled pieces came from
// islands solved exactly by pivoting at the acceleration level, a piece resting on an edge with
// its other corners 10 um up (a pair projection had turned it), and 24 from the impulse stage.
// Two changes brought it to rest: what one pass of pair projections leaves too deep is projected
// island by island with friction (island_projection.h), and the collision stage repeats until no
// touching contact approaches (baraff/collisions.cpp).
TEST_CASE("pile, Baraff: after 5 s all 100 pieces rest inside the bin", "[.][contact][pile]") {
  PileOutcome out = runPile(5);
  CHECK(out.speed < 1e-3);
  CHECK(out.spin < 1e-2);
  CHECK(out.penetration < 1e-3);
}

// The same 5 s with the scene as a user runs it: sleeping on (the scene default; runScene turns it
// off for the solver tests), so that islands at rest freeze until touched. At 065c393: every
// piece asleep at 5 s, no pair deeper than 1.0e-6 m (0.047 m/s and 72 of 100 asleep at bdff5fc).
TEST_CASE("pile, Baraff: after 5 s with sleeping all 100 pieces rest inside the bin", "[.][contact][pile][sleep]") {
  PileOutcome out = runPile(5, [](Scene& s) { s.simulation.step.sleep.enabled = true; });
  CHECK(out.speed < 1e-3);
  CHECK(out.spin < 1e-2);
  CHECK(out.penetration < 1e-3);
}

// And with every resting island solved at the velocity level with its near contacts
// ("pivoting_max_rows": 0; baraff/resting_forces.cpp, solveAtVelocityLevel), sleeping off; no
// island is small enough to pivot then, so only the repeated collision stage is new here. At
// 065c393: 3.7e-9 m/s, 8.6e-9 rad/s, 1.0e-6 m deep (4.4e-3 m/s and 8.1e-3 m deep at bdff5fc).
TEST_CASE("pile, Baraff: after 5 s with every island at the velocity level all 100 pieces rest inside the bin", "[.][contact][pile]") {
  PileOutcome out = runPile(5, [](Scene& s) { s.simulation.step.contact.max_direct_rows = 0; });
  CHECK(out.speed < 1e-3);
  CHECK(out.spin < 1e-2);
  CHECK(out.penetration < 1e-3);
}

// The pile as a user runs it, at the defaults: auto sees 100 pieces start free, a crowd of
// landings, and runs it by time stepping with ten Gauss-Seidel sweeps (dynamics/auto/auto_model.h).
// Its first second falls into the bin with no numerical fault (the run-time check stops the run
// on one); overlaps while the pieces land are time stepping's (docs/known-limits.md).
TEST_CASE("pile at the defaults: auto runs it by time stepping, the first second falls into the bin without a fault",
          "[contact][pile][auto]") {
  test::SceneRun run = test::runScene("pile", 1, {}, 30);
  INFO(run.counters.model_choice);
  CHECK(run.counters.model_choice.find("auto chose time stepping") != std::string::npos);
  World start = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/pile.json")).world;
  const std::vector<BodySample>& end = run.trajectory.frames.back();
  int outside = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (start.bodies[i].is_static) continue;
    const BodySample& b = end[i];
    if (std::abs(b.x.x()) > kInside || std::abs(b.x.y()) > kInside || b.x.z() < 0) ++outside;
  }
  CHECK(outside == 0);
}
