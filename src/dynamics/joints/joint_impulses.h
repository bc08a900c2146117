// The joints at the velocity level, as the time-stepping model treats contacts (Moreau 1988;
// Stewart and Trinkle 1996): one impulse problem per step on the velocities after the applied
// impulses,
//   equality rows   J v+ = 0
//   limit rows      J v+ >= -C / dt (a hinge may reach its limit within the step, never pass it)
//   velocity motor  J v+ = target, |p| <= max torque * dt
// solved exactly by pivoting (joint_rows.h).
#pragma once

#include "dynamics/world.h"

namespace tumble {

void applyJointStepImpulses(World& world, double dt);

}  // namespace tumble
