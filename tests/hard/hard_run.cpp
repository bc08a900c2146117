#include "hard_run.h"

#include <cmath>
#include <stdexcept>

#include "scene/world_builder.h"
#include "scene/scene_loader.h"

namespace tumble::hard {

Scene loadHardScene(const std::string& name) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/hard/" + name + ".json");
  // The hard cases hold the contact solve to their thresholds: sleeping, which would freeze
  // whatever it reached, is off unless a test turns it on.
  scene.simulation.step.sleep.enabled = false;
  return scene;
}

HardRun simulate(const Scene& scene, double seconds, const std::function<bool(const World&)>& on_step) {
  BuiltWorld built = buildWorld(scene);
  return simulate(std::move(built.world), built.step, seconds, on_step);
}

HardRun simulate(World world, const StepSettings& step, double seconds,
                 const std::function<bool(const World&)>& on_step) {
  HardRun run{std::move(world), {}, 0};
  Pipeline pipeline(run.world, step);
  const long steps = std::lround(seconds / step.dt);
  for (long k = 1; k <= steps; ++k) {
    pipeline.step(run.world, step);
    run.world.time = static_cast<double>(k) * step.dt;
    run.steps = k;
    if (on_step && !on_step(run.world)) break;
  }
  run.counters = pipeline.counters();
  return run;
}

int bodyIndex(const World& world, const std::string& name) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i)
    if (world.bodies[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument("no body named " + name);
}

const RigidBody& bodyNamed(const World& world, const std::string& name) {
  return world.bodies[bodyIndex(world, name)];
}

double kineticEnergy(const World& world) {
  double e = 0;
  for (const RigidBody& b : world.bodies) e += b.kineticEnergy();
  return e;
}

Eigen::Vector3d linearMomentum(const World& world) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const RigidBody& b : world.bodies) p += b.P;
  return p;
}

}  // namespace tumble::hard
