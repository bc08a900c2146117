// Back-stepping finds the first contact time: by bisection (default) and by regula falsi, on a
// closed-form depth and on the cube drop.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/simulator.h"
#include "dynamics/baraff/time_of_impact.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

TEST_CASE("bisection and regula falsi bracket the time a falling point reaches the ground", "[contact]") {
  // A point falling from 1 mm above the ground at 2 m/s: depth(t) = 2 t - 0.001, touching at 0.5 ms.
  auto depth = [](double t) { return 2 * t - 0.001; };
  const double h = 1.0 / 240, tol = 1e-6;
  for (bool falsi : {false, true}) {
    INFO((falsi ? "regula falsi" : "bisection"));
    ImpactSearch found = findFirstContact(depth, h, depth(h), tol, 60, falsi);
    CHECK(std::abs(depth(found.time)) <= tol);   // touching within the tolerance
    CHECK(found.time <= 0.0005 + tol / 2);
  }
  // On a linear depth the secant lands on the root at once (after evaluating the start).
  CHECK(findFirstContact(depth, h, depth(h), tol, 60, true).evaluations == 2);
  CHECK(findFirstContact(depth, h, depth(h), tol, 60, false).evaluations > 2);
}

TEST_CASE("the cube drop's impact time is the same with regula falsi", "[contact]") {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/cube_drop.json");
  auto impact = [&](bool falsi) {
    BuiltWorld built = buildWorld(scene);
    built.step.contact.regula_falsi = falsi;
    Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, 16});
    sim.run();
    return sim.pipeline().counters();
  };
  PipelineCounters halving = impact(false), secant = impact(true);
  REQUIRE_FALSE(halving.impact_times.empty());
  REQUIRE_FALSE(secant.impact_times.empty());
  CHECK(std::abs(secant.impact_times.front() - std::sqrt(2 / 9.81)) < 1e-4);
  CHECK(std::abs(secant.impact_times.front() - halving.impact_times.front()) < 1e-6);
  CHECK(secant.bisection_evaluations <= halving.bisection_evaluations);
}
