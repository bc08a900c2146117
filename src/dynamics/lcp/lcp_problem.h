// The (mixed, boxed) linear complementarity problem solved for contact forces and impulses.
//
//   w = A f + b,   lo ≤ f ≤ hi,   and for every i exactly one of
//     f_i = lo_i  and  w_i ≥ 0        (at the lower bound: a normal force of zero, contact separating)
//     f_i = hi_i  and  w_i ≤ 0        (at the upper bound: friction saturated, contact sliding)
//     lo_i < f_i < hi_i  and  w_i = 0 (clamped: the constraint holds with equality)
//
// With lo = 0 and hi = +inf this is the plain LCP  w ≥ 0, f ≥ 0, wᵀf = 0  of Baraff's resting
// contact (Baraff 1994, conditions I–III; Baraff, "Collision and Contact", course notes: "the resting-contact QP"). Friction follows ODE's
// "findex" convention (Xiang, "Robot Control and Physical Simulation", 2020: friction cones): if friction_of[i] = k ≥ 0 the bounds of variable i
// are not lo_i, hi_i but ±mu_i·f_k, where variable k is the normal force of the same contact.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace tumble::lcp {

struct LcpProblem {
  Eigen::MatrixXd A;              // n×n, symmetric positive semi-definite (A = J M⁻¹ Jᵀ)
  Eigen::VectorXd b;              // n
  Eigen::VectorXd lo, hi;         // n; bounds when friction_of[i] < 0; hi may be +inf, lo may be -inf
  std::vector<int> friction_of;   // n or empty; k ≥ 0 makes i a friction variable of normal k
  Eigen::VectorXd mu;             // n or empty; friction coefficient of i (if friction_of[i] ≥ 0)

  int size() const { return static_cast<int>(b.size()); }
  bool isFriction(int i) const { return !friction_of.empty() && friction_of[i] >= 0; }

  // A plain LCP (lo = 0, hi = +inf, no friction).
  static LcpProblem plain(Eigen::MatrixXd A, Eigen::VectorXd b);
};

enum class LcpStatus {
  Solved,         // converged; residuals below the solver's tolerance
  MaxIterations,  // pivot / iteration / friction-pass cap reached; f is the last iterate
  Failed,         // no solution found (unbounded ray: the LCP is infeasible) or non-finite input
};

const char* toString(LcpStatus status);

struct LcpResidual {
  double complementarity = 0;  // max over i of how far (f_i, w_i) is from its complementarity condition
  double bounds = 0;           // max over i of how far f_i lies outside [lo_i, hi_i] (friction: ±mu f_k)
};

struct LcpResult {
  Eigen::VectorXd f;           // the unknowns (forces or impulses)
  Eigen::VectorXd w;           // A f + b, recomputed from f at the end (accelerations or velocities)
  LcpStatus status = LcpStatus::Failed;
  int iterations = 0;          // Dantzig: pivots (all passes); PGS: sweeps
  int friction_passes = 0;     // Dantzig: passes of the friction-bound fixed point (0 without friction)
  LcpResidual residual;
};

// Bounds of every variable, friction bounds evaluated at the normal forces in f.
void effectiveBounds(const LcpProblem& p, const Eigen::VectorXd& f, Eigen::VectorXd& lo,
                     Eigen::VectorXd& hi);

// Residual measures of a candidate (f, w = A f + b). Complementarity is the natural (min-map)
// residual  max_i |f_i − mid(lo_i, f_i − w_i, hi_i)|:  for w_i > 0 it is min(f_i − lo_i, w_i), for
// w_i < 0 it is min(hi_i − f_i, −w_i), so it is zero exactly when one of the three conditions above
// holds, and it is small only if either the force sits at its bound or the acceleration is small.
// Friction bounds are evaluated at the normal forces in f.
LcpResidual measureResidual(const LcpProblem& p, const Eigen::VectorXd& f, const Eigen::VectorXd& w);

// The size of the terms a candidate's residuals are judged against: |b| + max_i sum_k |A_ik f_k| +
// |f| (max norms), what cancels in w = A f + b. Allocates nothing.
double termScale(const LcpProblem& p, const Eigen::VectorXd& f);

// Checks sizes, finiteness of A and b, lo ≤ hi and friction indices. Returns an empty string when valid.
const char* validate(const LcpProblem& p);

}  // namespace tumble::lcp
