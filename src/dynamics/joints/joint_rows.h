// Joints as rows of the constraint Jacobian (Baraff, "Linear-time dynamics using Lagrange
// multipliers", SIGGRAPH 1996; Featherstone, "Rigid Body Dynamics Algorithms", 2008): a row's
// velocity is J v = lin_a.v_a + ang_a.w_a + lin_b.v_b + ang_b.w_b, and a force f along it acts
// on the bodies as J^T f (force lin f and torque ang f on each side).
//
//   ball    3 linear rows along the world axes: the anchor points' gap, e . (p_b - p_a) = 0
//   hinge   the ball's 3, and 2 angular rows across the axis: (w_b - w_a) . n = 0
//   fixed   the ball's 3, and 3 angular rows along the world axes
//   limit   a hinge at or past a limit: one unilateral row about the axis, f >= 0 pushing back
//   motor   a velocity motor: one row about the axis, |f| <= its torque bound
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "dynamics/joints/joint.h"
#include "dynamics/world.h"

namespace tumble {

struct JointRow {
  enum class Kind { Equality, Limit, Motor };
  Kind kind = Kind::Equality;
  int a = -1, b = -1;                                               // -1: the world
  Eigen::Vector3d lin_a = Eigen::Vector3d::Zero(), ang_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d lin_b = Eigen::Vector3d::Zero(), ang_b = Eigen::Vector3d::Zero();
  double error = 0;   // the position error C (m or rad) whose rate is J v; >= 0 allowed for a limit
  double bias = 0;    // J' v: the row's acceleration when both bodies' accelerations are zero
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  double target_velocity = 0;   // a velocity motor's (rad/s)
  int joint = -1;               // index into World::joints
};

// Which rows a solve takes.
struct RowChoice {
  bool equality = true;
  // Limit rows of hinges within `limit_slop` rad of a limit, or past it.
  bool limits = true;
  double limit_slop = 1e-6;
  bool motors = false;          // velocity motors' rows
  double motor_torque_scale = 1;   // the motor row's bound: max torque times this (dt for impulses)
};

// The rows of every joint in the world's present state, in joint order.
void buildJointRows(const World& world, const RowChoice& choice, std::vector<JointRow>& rows);

// J v of one row in the world's present state.
double jointRowVelocity(const World& world, const JointRow& row);

// A = J M^-1 J^T (static bodies and the world have no inverse mass).
Eigen::MatrixXd jointDelassus(const World& world, const std::vector<JointRow>& rows);

// Solves w = A f + b with each f within its row's bounds (bilateral rows w = 0, a limit w >= 0
// where f is 0, a motor at its bound where w cannot reach 0), by pivoting (lcp/dantzig_solver.h):
// exact to rounding, and redundant rows (two joints that say the same) stay out of the factor.
Eigen::VectorXd solveJointRows(const std::vector<JointRow>& rows, const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

// Applies impulses p along the rows to the bodies' momenta (P += lin p, L += ang p).
void applyJointImpulses(World& world, const std::vector<JointRow>& rows, const Eigen::VectorXd& p);

}  // namespace tumble
