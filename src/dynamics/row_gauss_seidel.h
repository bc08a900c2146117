// Projected Gauss-Seidel over contact rows without forming A = J M^-1 J^T (Xiang, "Robot Control and Physical Simulation", 2020: "physical
// simulators typically use projected Gauss-Seidel"). Each body keeps M^-1 J^T f, the acceleration
// the forces found so far give it, so visiting a row costs a few dot products, not a row of A: a
// sweep is linear in the number of rows, where the pivoting solver's cost grows with their cube.
// The resting-force solve uses it for islands too large for pivoting (a pile: hundreds of boxes
// touching in one island), and as the fallback when pivoting does not converge.
//
// The same iteration solves the velocity-level problem of the time-stepping model: there f is an
// impulse, b a velocity, and the rows' targets are velocities.
//
// Rows are visited in index order (deterministic). Per row, with w = J_i a + b_i its acceleration:
//   Normal  f <- max(0, f - w / A_ii)                           (push, never pull)
//   Static  f <- mid(-mu f_n, f - w / A_ii, mu f_n)             (tangential acceleration 0 if it can)
//   Sliding f <- mid(0, f + (target - w) / A_ii, mu f_n)        (oppose the slide; bring it to rest
//           within `target`'s time at most: never more than mu f_n, never reversing the slide)
// where f_n is the latest force of the contact's normal row.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_jacobian.h"
#include "dynamics/world.h"

namespace tumble {

struct RowLimit {
  enum Kind { Normal, Static, Sliding } kind = Normal;
  int normal = -1;       // Static, Sliding: index of the contact's normal row
  double mu = 0;         // Static, Sliding: friction coefficient
  double target = 0;     // Sliding: the acceleration along the row that would stop the slide
};

struct RowGaussSeidelSettings {
  int max_sweeps = 200;
  // Converged when a sweep changes no row's acceleration by more than this fraction of the
  // largest free acceleration (|b|, gravity's size in a pile).
  double tolerance = 1e-7;
};

struct RowGaussSeidelSweeps {
  int sweeps = 0;
  bool converged = false;
  // The largest change of any row's acceleration in the last sweep (NaN if one was not finite):
  // how far from a fixed point the answer is, in the units of the tolerance.
  double last_change = 0;
};

struct RowGaussSeidelResult : RowGaussSeidelSweeps {
  Eigen::VectorXd f;     // force along each row (N)
};

// `start` (if it has one entry per row) is the first guess: the time-stepping model passes the
// impulses of the last step (warm start), which leaves few sweeps for a pile at rest.
RowGaussSeidelResult solveRowsGaussSeidel(const World& world, const std::vector<ContactRow>& rows,
                                          const Eigen::VectorXd& b, const std::vector<RowLimit>& limits,
                                          const RowGaussSeidelSettings& settings = {},
                                          const Eigen::VectorXd& start = {});

// The same solve in place, allocating nothing once its buffers have grown to the island: `f` (one
// entry per row) holds the first guess on entry and the answer on exit.
RowGaussSeidelSweeps sweepRowsGaussSeidel(const World& world, const std::vector<ContactRow>& rows,
                                          Eigen::Ref<const Eigen::VectorXd> b, const std::vector<RowLimit>& limits,
                                          const RowGaussSeidelSettings& settings, Eigen::Ref<Eigen::VectorXd> f);

}  // namespace tumble
