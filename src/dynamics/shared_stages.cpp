#include "dynamics/shared_stages.h"

#include <algorithm>

namespace tumble {
namespace {

const char* kStageNames[] = {"detect", "collide", "forces", "resting", "integrate", "back-step", "correct", "sleep"};
static_assert(sizeof kStageNames / sizeof kStageNames[0] == StageCount);

int countMoving(const World& world) {
  int n = 0;
  for (const RigidBody& b : world.bodies) n += b.is_static ? 0 : 1;
  return n;
}

}  // namespace

SharedStages::SharedStages(const World& world)
    : apply_gravity(world.gravity.squaredNorm() > 0),
      moving(countMoving(world)),
      fixed(static_cast<int>(world.bodies.size()) - moving),
      detector(world),
      has_contacts(detector.hasCollidablePairs()),
      min_thickness(detector.thinnestPiece()),
      sleep(world),
      wrenches(world.bodies.size()) {
  extents = extentsOf(world);
  for (const BodyExtent& e : extents) body_radius.push_back(e.radius);
  for (const char* name : kStageNames) profile.push_back({name});
}

std::string SharedStages::movingBodies() const {
  return std::to_string(moving) + (moving == 1 ? " moving body" : " moving bodies");
}

std::string SharedStages::integrateLine(const StepSettings& settings) const {
  return std::string("integrate   ") + (settings.integrator == Integrator::Rk4 ? "RK4" : "semi-implicit Euler") +
         ", dt = " + std::to_string(settings.dt) + " s, " + movingBodies() + "; " + std::to_string(fixed) +
         " static never integrated";
}

void SharedStages::notePeakSpeeds(const World& world) {
  for (std::size_t k = 0; k < world.bodies.size() && k < peak_speed.size(); ++k) {
    const RigidBody& body = world.bodies[k];
    if (body.is_static) continue;
    peak_speed[k] = std::max(peak_speed[k], body.velocity().norm());
    peak_spin[k] = std::max(peak_spin[k], body.angularVelocity().norm());
  }
}

}  // namespace tumble
