#include "dynamics/pipeline.h"

#include <chrono>

#include "dynamics/gravity.h"

namespace tumble {
namespace {

// Times one stage and adds its wall time to the stage's entry in the profile.
template <typename F>
void timed(StageTime& entry, F&& stage) {
  auto start = std::chrono::steady_clock::now();
  stage();
  entry.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int movingBodies(const World& world) {
  int n = 0;
  for (const RigidBody& b : world.bodies) n += b.is_static ? 0 : 1;
  return n;
}

}  // namespace

Pipeline::Pipeline(const World& world, const StepSettings& settings)
    : apply_gravity_(world.gravity.squaredNorm() > 0),
      moving_(movingBodies(world)),
      static_(static_cast<int>(world.bodies.size()) - moving_),
      integrator_(settings.integrator),
      dt_(settings.dt),
      wrenches_(world.bodies.size()) {
  if (apply_gravity_) profile_.push_back({"forces"});
  profile_.push_back({"integrate"});
}

void Pipeline::step(World& world, const StepSettings& settings) {
  std::size_t stage = 0;
  if (apply_gravity_) timed(profile_[stage++], [&] { applyGravity(world, wrenches_); });
  timed(profile_[stage++], [&] { integrate(world, wrenches_, settings); });
  world.time += settings.dt;
}

std::vector<std::string> Pipeline::describe() const {
  std::vector<std::string> lines;
  std::string moving = std::to_string(moving_) + (moving_ == 1 ? " moving body" : " moving bodies");
  if (apply_gravity_) lines.push_back("forces      gravity on " + moving);
  lines.push_back(std::string("integrate   ") +
                  (integrator_ == Integrator::Rk4 ? "RK4" : "semi-implicit Euler") + ", dt = " +
                  std::to_string(dt_) + " s, " + moving + "; " + std::to_string(static_) +
                  " static never integrated");
  lines.push_back("contacts    none: the contact pipeline is not built yet, bodies pass through "
                  "each other");
  return lines;
}

}  // namespace tumble
