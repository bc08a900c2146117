#include "dynamics/joints/pd_motor.h"

#include <cmath>

namespace tumble {

double motorTorque(const World& world, const Joint& j) {
  // The error the shorter way round: a target of 170 deg seen from -170 deg is 20 deg away.
  double error = j.motor.target_rad - hingeAngle(world, j);
  error = std::remainder(error, 2 * M_PI);
  return j.motor.kp * error - j.motor.kd * hingeRate(world, j);
}

void addMotorTorques(const World& world, std::vector<Wrench>& wrenches) {
  for (const Joint& j : world.joints) {
    if (j.type != JointType::Hinge || j.motor.kind != JointMotor::Kind::Position) continue;
    const JointSide sa = jointSide(world, j.a);
    const Eigen::Vector3d torque = motorTorque(world, j) * (sa.R * j.axis_a);
    if (sa.moves()) wrenches[j.a].torque -= torque;
    const JointSide sb = jointSide(world, j.b);
    if (sb.moves()) wrenches[j.b].torque += torque;
  }
}

}  // namespace tumble
