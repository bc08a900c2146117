// The joints' constraint forces at the acceleration level (Baraff, "Linear-time dynamics using
// Lagrange multipliers", 1996): with the applied wrenches W, the multipliers f solve
//   J M^-1 (W + J^T f) + J' v = 0
// (for a limit row: >= 0 with f >= 0; a velocity motor's row asks for the acceleration that
// reaches its target speed within the step, |f| at most its torque). J' v holds the centripetal
// terms and each body's gyroscopic acceleration -I^-1 (w x L), so the forces hold the joints to
// second order, and the integrator evaluates them at each of its stages (joint_integrator.h).
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/joints/joint_rows.h"
#include "dynamics/world.h"

namespace tumble {

// How the joints' constraint forces hold them over a step.
enum class JointHold {
  // J a + J' v = 0 (above): second order along the path, for an integrator that evaluates the
  // forces at each of its stages (RK4).
  Acceleration,
  // J v + dt J a = 0: each row's velocity zero at the step's end, the velocity level of Bullet's
  // and ODE's joints, for an integrator that holds the forces over the step (semi-implicit Euler).
  // Held there at the acceleration level, the centripetal pull, explicit in the speed, fed energy
  // into a whip at every step (joint_integrator.h).
  Velocity,
};

// Adds the PD motors' torques and the joints' constraint forces for the world's present state to
// `wrenches` (one per body, holding the applied forces). `dt`: the step a velocity motor's target
// is to be reached within, and the step a Velocity hold holds over; `velocity_motors` false leaves
// their rows out.
void addJointForces(const World& world, std::vector<Wrench>& wrenches, double dt, bool velocity_motors = true,
                    JointHold hold = JointHold::Acceleration);

// The rows of that problem and their b (J a + J' v under `applied`, less a velocity motor's
// target acceleration), for a solve that takes them with other rows (the Baraff model's resting
// contacts, contact_joint_lcp.h). `motors`: whether velocity motors' rows are among them.
void jointAccelerationRows(const World& world, const std::vector<Wrench>& applied, double dt, bool motors,
                           std::vector<JointRow>& rows, Eigen::VectorXd& b,
                           JointHold hold = JointHold::Acceleration);

}  // namespace tumble
