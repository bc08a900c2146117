// A hinge's PD motor (the robot-control lecture's controller): tau = kp (target - theta) - kd
// theta_dot, about the hinge axis, on b and its opposite on a, so that it turns the two against
// each other and adds no net torque to the pair. Evaluated wherever the forces are (every stage of
// the integrator: joint_forces.h), so a stiff gain is integrated as accurately as gravity.
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

// Adds every PD motor's torque pair to `wrenches` (one per body) for the world's present state.
void addMotorTorques(const World& world, std::vector<Wrench>& wrenches);

// The torque of one joint's PD motor about its axis (N m) in the world's present state.
double motorTorque(const World& world, const Joint& joint);

}  // namespace tumble
