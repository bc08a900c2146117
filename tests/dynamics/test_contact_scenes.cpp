// The contact pipeline against closed forms, on the benchmark scenes (docs/bench/scenes.md) at
// dt = 1/240 s with default settings. The thresholds are the contact pipeline's acceptance bounds;
// where they came from is said beside each.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact_scene_runner.h"

using namespace tumble;
using tumble::test::runScene;

namespace {

const BodySample& last(const test::SceneRun& run, int body) { return run.trajectory.frames.back()[body]; }
const BodySample& first(const test::SceneRun& run, int body) { return run.trajectory.frames.front()[body]; }

}  // namespace

TEST_CASE("cube drop: impact time, bounce apex and no spin", "[contact]") {
  double apex = 0, max_w = 0;
  bool rising = false, done = false;
  auto run = runScene("cube_drop", 2, [&](const World& w) {
    const RigidBody& cube = w.bodies[1];
    max_w = std::max(max_w, cube.angularVelocity().norm());
    if (cube.velocity().z() > 0.05) rising = true;
    if (rising && !done) apex = std::max(apex, cube.x.z());
    if (rising && cube.velocity().z() <= 0) done = true;
  });
  REQUIRE_FALSE(run.counters.impact_times.empty());
  // Its four corners were counted as colliding contacts (-v prints the count).
  CHECK(run.counters.contacts.colliding >= 4);
  // The impact is found by bisection to within the contact tolerance (1e-6 m at 4.4 m/s: 2e-7 s).
  CHECK(std::abs(run.counters.impact_times.front() - std::sqrt(2 / 9.81)) < 1e-4);
  // Apex 0.5 + e^2 h = 0.75 m within 0.5 %: the bounce is exact up to the step's sampling of the apex.
  CHECK(std::abs(apex - 0.75) < 0.005 * 0.75);
  // Four corners land at once and are solved together: no spin at all.
  CHECK(max_w < 1e-9);
}

TEST_CASE("rest: a cube on the ground does not move or sink", "[contact]") {
  double max_speed = 0;
  auto run = runScene("rest", 10, [&](const World& w) {
    if (w.time >= 1) max_speed = std::max(max_speed, w.bodies[1].velocity().norm() +
                                                      w.bodies[1].angularVelocity().norm());
  });
  CHECK(run.max_penetration < 1e-6);
  CHECK(max_speed < 1e-6);
  CHECK((last(run, 1).x - first(run, 1).x).norm() < 1e-6);
}

TEST_CASE("incline: the cube slides by the closed form, or sticks", "[contact]") {
  SECTION("mu = 0.3 slides 0.5 g (sin 30 - mu cos 30) t^2") {
    auto run = runScene("incline_slide", 2);
    double expected = 0.5 * 9.81 * (0.5 - 0.3 * std::cos(M_PI / 6)) * 4;
    // RK4 integrates the constant acceleration exactly; 1e-3 m is the acceptance bound.
    CHECK(std::abs(-last(run, 1).x.x() - expected) < 1e-3);
    CHECK(last(run, 1).w.norm() < 1e-9);
  }
  SECTION("mu = 0.7 sticks (mu > tan 30)") {
    auto run = runScene("incline_stick", 2);
    CHECK((last(run, 1).x - first(run, 1).x).norm() < 1e-6);
  }
}

TEST_CASE("mass ratio 1000:1 stays stacked without penetrating", "[contact]") {
  auto run = runScene("mass_ratio", 5);
  CHECK(run.max_penetration < 1e-5);
  CHECK(std::abs(last(run, 2).x.z() - 1.5) < 1e-5);
  CHECK(last(run, 2).x.head<2>().norm() < 1e-5);
}

TEST_CASE("tunnel: no cube passes through a 1 cm wall at 100 m/s", "[contact]") {
  auto run = runScene("tunnel", 0.2);
  for (std::size_t j = 1; j < run.trajectory.body_names.size(); ++j) {
    INFO(run.trajectory.body_names[j]);
    CHECK(last(run, static_cast<int>(j)).x.x() < 5.0);
  }
}

// The tunnelling bound looks at pairs that can meet within the step, by their approach along the
// separating axis: the cubes fly uncut until the step in which they reach the wall. A bound by
// the fastest body against the thinnest piece (as before b5c78a8, 2026-11-23) cut every step of
// this scene into 0.01 m / (4 * 100 m/s) = 25 us sub-steps: 167 per step, 8000 in all.
TEST_CASE("tunnel: steps are cut only where a cube reaches the wall", "[contact]") {
  auto run = runScene("tunnel", 0.2);
  const long steps = 48;   // 0.2 s at 1/240 s
  INFO(run.counters.substeps << " sub-steps, " << run.counters.back_steps << " back-steps");
  CHECK(run.counters.substeps < steps + 10 * 4);   // at most a few extra per cube's impact
  CHECK(run.counters.stuck_substeps == 0);
}
