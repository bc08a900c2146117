// The slowest impact that bounces depends on the contact's normal (BounceThreshold,
// contact_solve_common.h). Gravity takes a bounce off the floor back within a step or two, so
// landings slower than 2 g dt settle; it takes nothing from a bounce off a wall, so a slow impact
// there keeps its restitution. A single bound of 2 g dt for every normal (0.082 m/s at dt =
// 1/240 s) stopped a box sliding into a wall at 5 cm/s dead, e = 0.5 or not.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "dynamics/simulator.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

// A 0.2 m cube on frictionless ground, sliding at `speed` towards a wall 0.1 m away (or, with
// `drop`, falling onto the ground from rest); e = 0.5 everywhere. Returns the cube's velocity
// after `seconds`.
Eigen::Vector3d cubeAfter(ContactModel model, double speed, bool drop, double seconds) {
  const std::string text = std::string(R"({"schema_version": 1, "render": {"fps": 30, "duration_s": )") +
                           std::to_string(seconds) + R"(},
    "simulation": {"dt_s": 0.004166666666666667},
    "bodies": [
      {"name": "ground", "shape": "plane", "friction": 0, "restitution": 0.5},
      {"name": "wall", "shape": "box", "size_m": [0.1, 2, 1], "position_m": [0.25, 0, 0.5], "static": true,
       "friction": 0, "restitution": 0.5},
      {"name": "cube", "shape": "box", "size_m": [0.2, 0.2, 0.2], "friction": 0, "restitution": 0.5,
       "position_m": [0, 0, )" + std::string(drop ? "0.1002" : "0.1") + R"(],
       "velocity_m_s": [)" + std::to_string(drop ? 0.0 : speed) + R"(, 0, 0]}]})";
  Scene scene = parseScene(text, "wall_bounce.json");
  scene.simulation.step.model = model;
  scene.simulation.step.sleep.enabled = false;
  BuiltWorld built = buildWorld(scene);
  Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  sim.run({}, [&](const World& w) { v = w.bodies[2].velocity(); });
  return v;
}

}  // namespace

TEST_CASE("a slow impact on a wall bounces with its restitution (both models), and a slow landing on the floor settles",
          "[impulse][restitution]") {
  for (ContactModel model : {ContactModel::Baraff, ContactModel::TimeStepping}) {
    for (double speed : {0.02, 0.05}) {   // both below 2 g dt = 0.082 m/s
      INFO((model == ContactModel::Baraff ? "Baraff" : "time stepping") << ", " << speed << " m/s into the wall");
      // The wall is reached within 0.1 / 0.02 = 5 s at the slowest; 6 s leaves it on its way back.
      const Eigen::Vector3d v = cubeAfter(model, speed, false, 6);
      // Newton's law on a frictionless face: the rebound is e times the approach, to rounding.
      CHECK(v.x() == Approx(-0.5 * speed).epsilon(1e-9));
    }
    // Dropped 0.2 mm, the cube lands at sqrt(2 g h) = 0.063 m/s, below 2 g dt: it settles on the
    // floor instead of bouncing at a height gravity undoes within a step.
    INFO((model == ContactModel::Baraff ? "Baraff" : "time stepping") << ", landing on the floor");
    const Eigen::Vector3d v = cubeAfter(model, 0, true, 0.5);
    CHECK(std::abs(v.z()) < 1e-3);
  }
}
