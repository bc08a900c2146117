// The joints at the velocity level, as the time-stepping model treats contacts (Moreau 1988;
// Stewart and Trinkle 1996): one impulse problem per step on the velocities after the applied
// impulses,
//   equality rows   J v+ = 0
//   limit rows      J v+ >= -C / dt (a hinge may reach its limit within the step, never pass it)
//   velocity motor  J v+ = target, |p| <= max torque * dt
// solved exactly by pivoting (joint_rows.h).
#pragma once

#include <vector>

#include "dynamics/joints/joint_rows.h"
#include "dynamics/world.h"

namespace tumble {

// The rows of the step's joint problem and their b (w = A p + b, b = J v less each row's target).
void jointStepRows(const World& world, double dt, std::vector<JointRow>& rows, Eigen::VectorXd& b);

// Solves and applies the joints' impulses alone (a world with nothing that can touch; with
// contacts they are solved together, contact_joint_lcp.h).
void applyJointStepImpulses(World& world, double dt);

}  // namespace tumble
