// The default LCP solver: a direct principal-pivoting method (Cottle–Dantzig; Baraff, "Fast contact
// force computation for nonpenetrating rigid bodies", 1994, the "fast solver") for the
// boxed problem of lcp_problem.h, with ODE's friction-dependent bounds. Its answer is exact to
// rounding: every clamped variable satisfies w_i = 0 through a Cholesky solve, not an iteration.
#pragma once

#include "dynamics/lcp/lcp_problem.h"

namespace tumble::lcp {

struct DantzigSettings {
  // Hard cap on pivots per pass: max_pivots_per_variable·n + 16. Each variable is driven once and a
  // drive rarely takes more than a few pivots; the cap turns a pathological (cycling) case into
  // LcpStatus::MaxIterations instead of a hang.
  int max_pivots_per_variable = 16;
  // Relative Schur complement below which a variable counts as a linear combination of the clamped
  // set (a redundant contact) and is kept out of it: s_j ≤ tol·A_jj, i.e. the part of its
  // Jacobian row outside the clamped rows is below sqrt(tol) ≈ 3e-5 of its length. Rounding in s_j
  // is about cond(A_CC)·1e-16, so this leaves room for clamped sets with cond up to ~1e6.
  double dependence_tolerance = 1e-9;
  // Relative noise floor for the step directions Δf, Δw in the ratio test: changes smaller than
  // this times the scale (max_i A_ii for w, 1 for f) are rounding, not motion, and never block.
  double pivot_tolerance = 1e-12;
  // Relative tolerance on w_i (times |b_i| + Σ_k |A_ik f_k|, the size of the terms that cancel)
  // under which a variable already satisfies its condition when its turn comes.
  double residual_tolerance = 1e-13;
  // A redundant variable whose w cannot be moved (nothing blocks its drive) is accepted when
  // |w_i| ≤ this times the same scale: the redundant system is only as consistent as A and b are
  // accurate, and b is often a small difference of large terms. Beyond it: LcpStatus::Failed.
  double consistency_tolerance = 1e-9;
  // Friction: each pass solves a boxed LCP with the friction bounds ±mu·f_n fixed at the previous
  // pass's normal forces (pass 0: no friction); passes stop when the bounds change by less than
  // friction_tolerance·(1 + max bound), at most max_friction_passes.
  int max_friction_passes = 100;
  double friction_tolerance = 1e-13;
  // A pass after the first starts from the last pass's clamped set (BoxedPivoting::seed) instead
  // of driving every variable from zero again; off only to measure what that saves.
  bool seed_friction_passes = true;
  // An answer is reported LcpStatus::Solved only if its residuals, recomputed from A f + b, are
  // within this share of the size of its terms (|b| + |A| |f| + |f|); otherwise MaxIterations. A
  // solved answer's are at rounding (about 1e-13 of it, consistency_tolerance at most).
  double solved_tolerance = 1e-6;
};

// Solves p; lo ≤ 0 ≤ hi is not required (a variable starts at the bound nearest 0). A must be
// symmetric positive semi-definite for the termination and existence guarantees.
LcpResult solveDantzig(const LcpProblem& p, const DantzigSettings& settings = {});
// The same into `r`, whose vectors are reused: with the solver's own buffers (kept per thread), a
// problem of the size of the last allocates nothing unless it takes the friction fixed point's
// linear solve (friction_fixed_point.h).
void solveDantzig(const LcpProblem& p, const DantzigSettings& settings, LcpResult& r);

}  // namespace tumble::lcp
