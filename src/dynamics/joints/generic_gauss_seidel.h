// Projected Gauss-Seidel over generic rows (joint_rows.h): contact rows in their generic form and
// joint rows in one sweep, for the time-stepping model's problem with joints once it is too large
// to pivot (a joined body in a pile). Rows are visited in index order (deterministic); each keeps
// its bounds lo <= f <= hi, a friction row (friction_of >= 0) +-mu times its normal row's latest
// force. Each body keeps M^-1 J^T f, so a sweep costs linear time in the rows (as row_gauss_seidel.h,
// whose rows are contact rows only: a pure torque row, a hinge's, is not one).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/joints/joint_rows.h"
#include "dynamics/lcp/lcp_problem.h"

namespace tumble {

struct GenericSweeps {
  Eigen::VectorXd f;
  int sweeps = 0;
  bool converged = false;
};

// Solves w = A f + b within the problem's bounds (its A is not read: the rows give it), from `start`
// (one entry per row, or empty for zero), until no row's velocity changes by more than `tolerance`
// times the largest finite |b| in a sweep, at most `max_sweeps`. `one_sided` (one entry per row, or
// empty): friction rows whose force only opposes, 0 <= f <= mu f_n, a slide's dynamic friction
// (row_gauss_seidel.h's Sliding rows); such a row's b may be -inf, for mu f_n whatever the rest.
GenericSweeps solveGenericGaussSeidel(const World& world, const std::vector<JointRow>& rows, const lcp::LcpProblem& p,
                                      const Eigen::VectorXd& start, int max_sweeps, double tolerance,
                                      const std::vector<char>& one_sided = {});

}  // namespace tumble
