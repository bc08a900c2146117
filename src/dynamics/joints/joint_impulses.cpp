#include "dynamics/joints/joint_impulses.h"

#include <algorithm>
#include <numbers>
#include <vector>

#include "dynamics/joints/joint_rows.h"

namespace tumble {

void jointStepRows(const World& world, double dt, std::vector<JointRow>& rows, Eigen::VectorXd& b) {
  RowChoice choice;
  choice.motors = true;
  choice.motor_torque_scale = dt;
  // Every limited hinge's limit rows: one far from its limit takes no impulse (its gap is larger
  // than the step can close), and one near it is caught before it passes.
  choice.limit_slop = 2 * std::numbers::pi;
  buildJointRows(world, choice, rows);
  const int n = static_cast<int>(rows.size());
  b.resize(n);
  for (int i = 0; i < n; ++i) {
    const JointRow& r = rows[i];
    b[i] = jointRowVelocity(world, r);
    if (r.kind == JointRow::Kind::Limit) b[i] += std::max(r.error, 0.0) / dt;
    if (r.kind == JointRow::Kind::Motor) b[i] -= r.target_velocity;
  }
}

void applyJointStepImpulses(World& world, double dt) {
  std::vector<JointRow> rows;
  Eigen::VectorXd b;
  jointStepRows(world, dt, rows, b);
  if (rows.empty()) return;
  applyJointImpulses(world, rows, solveJointRows(rows, jointDelassus(world, rows), b));
}

}  // namespace tumble
