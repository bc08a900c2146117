// Runs a scene of scenes/hard/ without rendering: the world is stepped by the pipeline exactly as
// `tumble simulate` does, and the test sees the world after every step.
#pragma once

#include <functional>
#include <string>

#include "dynamics/pipeline.h"
#include "dynamics/world.h"
#include "scene/world_builder.h"
#include "scene/scene.h"

namespace tumble::hard {

// scenes/hard/NAME.json, loaded and validated.
Scene loadHardScene(const std::string& name);

struct HardRun {
  World world;                 // at the end
  PipelineCounters counters;
  long steps = 0;
};

// Steps the world built from `scene` for round(seconds / dt) steps of the scene's dt, calling
// `on_step` after each (world.time is k dt exactly, as in the Simulator). Stops early when
// `on_step` returns false.
HardRun simulate(const Scene& scene, double seconds, const std::function<bool(const World&)>& on_step = {});
// The same for a world built (and then changed) by the test.
HardRun simulate(World world, const StepSettings& step, double seconds,
                 const std::function<bool(const World&)>& on_step = {});

// The body of the world named `name` (the scene's body names are unique).
const RigidBody& bodyNamed(const World& world, const std::string& name);
int bodyIndex(const World& world, const std::string& name);

// Kinetic energy and momenta of all moving bodies.
double kineticEnergy(const World& world);
Eigen::Vector3d linearMomentum(const World& world);

}  // namespace tumble::hard
