#include "dynamics/motion_check.h"

#include <algorithm>
#include <cmath>

namespace tumble {

MotionCheck::MotionCheck(const World& world, const std::vector<BodyExtent>& extents, double depth_share) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    radius_.push_back(extents[i].radius);
    allowance_.push_back(std::isfinite(extents[i].thinnest) ? depth_share * extents[i].thinnest : 0.0);
    last_.push_back(stateOf(world.bodies[i]));
  }
}

MotionCheck::State MotionCheck::stateOf(const RigidBody& body) {
  if (body.is_static) return {body.x, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), body.q};
  return {body.x, body.velocity(), body.angularVelocity(), body.q};
}

void MotionCheck::remember(const World& world) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i) last_[i] = stateOf(world.bodies[i]);
}

std::optional<UnexplainedMotion> MotionCheck::afterStep(const World& world, double dt,
                                                        const std::vector<double>& peak_speed,
                                                        const std::vector<double>& peak_spin) {
  std::optional<UnexplainedMotion> worst;
  double worst_excess = 0;
  const double g = world.gravity.norm();
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& body = world.bodies[i];
    const State was = last_[i], now = stateOf(body);
    last_[i] = now;
    if (body.fixedByScene()) continue;
    // Every point of the body moves by at most |dx| + 2 r sin(theta / 2), theta the turn.
    const double turn = 2 * std::acos(std::min(1.0, std::abs(was.q.dot(now.q))));
    const double moved = (now.x - was.x).norm() + 2 * radius_[i] * std::sin(0.5 * turn);
    const double peak_v = i < peak_speed.size() ? peak_speed[i] : 0.0;
    const double peak_w = i < peak_spin.size() ? peak_spin[i] : 0.0;
    const double speed = std::max({was.v.norm(), now.v.norm(), peak_v}) + g * dt +
                         std::max({was.w.norm(), now.w.norm(), peak_w}) * radius_[i];
    const double allowed = speed * dt + allowance_[i];
    if (moved - allowed > worst_excess) {
      worst_excess = moved - allowed;
      worst = UnexplainedMotion{static_cast<int>(i), moved, allowed};
    }
  }
  return worst;
}

}  // namespace tumble
