// Contact problems with friction solved by Lemke's complementary pivoting: the solver that finds
// an answer wherever one exists, for when the friction passes of solveDantzig do not settle.
//
// solveDantzig freezes the friction bounds ±mu f_n at the last pass's normal forces and solves
// again until they stop moving. That fixed point need not contract: a light shard struck between
// a falling one and the ground (an untuned scene of 23 random shards, densities 100 to 10 000
// kg/m^3) had its 19-contact island stop after 12 passes with friction 0.08 N s past its bounds,
// and the Gauss-Seidel answer left in its place let the shard approach the ground at 3 m/s through
// a 1.4 mm gap: 11 mm deep by the step's end.
//
// Written with the friction bound as complementarity conditions instead of as a bound, the problem
// is one LCP (Stewart and Trinkle, "An implicit time-stepping scheme for rigid body dynamics with
// inelastic collisions and Coulomb friction", 1996; Anitescu and Potra, "Formulating dynamic
// multi-rigid-body contact problems with friction as solvable linear complementarity problems",
// 1997). The square pyramid |f_1|, |f_2| <= mu f_n of a contact's two friction rows is the cone
// of its four edges d_j = +-t1 +-t2: the friction is sum_j beta_j d_j with beta_j >= 0 and
// sum_j beta_j <= mu f_n, and a slack lambda (the sliding speed) makes it oppose sliding:
//
//   d_j' v + lambda >= 0  _|_  beta_j >= 0
//   mu f_n - sum_j beta_j >= 0  _|_  lambda >= 0
//
// Its matrix is copositive (A is positive semi-definite; the lambda coupling is skew but for the
// mu f_n term, which is non-negative), and where the normal rows ask no more than that bodies
// stop approaching (b = J v + c with c >= 0: gaps, no bounce targets) Anitescu and Potra show
// that Lemke's method ends in a solution. With bounce targets a body wedged between contacts may
// have none (the targets cannot all be met): Lemke's method then ends on a ray, LcpStatus::Failed.
// Rounding can defeat the path where the exact answer exists: faces of four coplanar corners
// make most bases near singular (a rocking tower's islands ended on false rays), and some
// problems have only answers of huge internal impulses (a shard jammed by friction: 6800 N s to
// change velocities by 0.04 m/s). The path is then followed on the problem regularised by a
// small diagonal (LemkeSettings::regularisation), whose answer is near, not exact.
// Dense: O(n^2) per pivot and an O(n^3) refactorisation every 16, on n = 6 per contact; a
// fallback for islands the direct solver could not settle, not the everyday solver.
#pragma once

#include "dynamics/lcp/lcp_problem.h"

namespace tumble::lcp {

struct LemkeSettings {
  // Pivots at most max_pivots_per_variable x n + 100 (the method takes about n to 2n): a cap that
  // turns rounding-driven cycling into LcpStatus::MaxIterations instead of a hang.
  int max_pivots_per_variable = 20;
  // A pivot element below this share of its column's largest magnitude is rounding, not a ratio.
  double pivot_tolerance = 1e-11;
  // Ratios within this relative distance of the least are ties (rounding splits true ties by
  // about 1e-12 of the ratio after a few dozen pivots), broken lexicographically.
  double tie_tolerance = 1e-9;
  // Where the path on the problem itself ends short of an exact answer, it is followed again with
  // this added to the diagonal of the impulses' rows (scaled to unit diagonal): the answer then
  // leaves each contact's velocity off by up to this share of its impulse's effect, and is
  // reported as LcpStatus::MaxIterations for the caller to judge. On three islands of a toppling
  // tower of crossed blocks where the plain path failed, 1e-7 answered all three (1e-8 two, 1e-10
  // none).
  double regularisation = 1e-7;
};

// Whether p has only what this formulation covers: plain rows (lo = 0, hi = +inf) and at most
// two friction rows of one coefficient per plain row.
bool lemkeCovers(const LcpProblem& p);

// Solves p into r (f, w = A f + b, residuals, pivots in iterations). Status: Solved when the
// answer's complementarity residual is within rounding of the terms; MaxIterations at the cap or
// for the regularised answer (its residuals say how near it is); Failed on a ray (no solution)
// or a problem lemkeCovers rejects.
void solveLemkeFriction(const LcpProblem& p, const LemkeSettings& settings, LcpResult& r);

}  // namespace tumble::lcp
