#include "dynamics/gravity.h"

namespace tumble {

void applyGravity(const World& world, std::vector<Wrench>& wrenches) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& body = world.bodies[i];
    wrenches[i].force = body.is_static ? Eigen::Vector3d::Zero() : Eigen::Vector3d(body.mass * world.gravity);
    wrenches[i].torque.setZero();
  }
}

void applyGravityImpulse(World& world, double dt) {
  for (RigidBody& b : world.bodies)
    if (!b.is_static) b.P += b.mass * world.gravity * dt;
}

}  // namespace tumble
