// Projected Gauss–Seidel for the boxed LCP of lcp_problem.h (Xiang, "Robot Control and Physical Simulation", 2020: "physical simulators
// typically use projected Gauss-Seidel" for mixed LCPs): the cheap, approximate alternative to
// solveDantzig. Each sweep visits i = 0..n−1 in index order (deterministic) and sets
//   f_i ← mid(lo_i, f_i − ω·w_i / A_ii, hi_i),   w_i = A_i· f + b_i with the latest f,
// the exact minimiser of the quadratic ½fᵀAf + bᵀf along coordinate i (ω = 1) projected on its box;
// friction bounds ±mu_i·f_k use the latest normal force f_k. It converges for A PSD with positive
// diagonal (a descent method on a convex QP) but only linearly, slowly when A is ill-conditioned.
#pragma once

#include "dynamics/lcp/lcp_problem.h"

namespace tumble::lcp {

struct PgsSettings {
  int max_iterations = 500;   // sweeps
  // Stop when a sweep changes no variable by more than tolerance·(‖b‖∞ + 1e-300) in w units
  // (|Δf_i|·A_ii, an acceleration for forces): relative to the size of the applied load.
  double tolerance = 1e-10;
  double sor = 1.0;           // over-relaxation ω in (0, 2); 1 is plain Gauss–Seidel
};

// warm_start (size n, or nullptr for zeros) is projected on the bounds before the first sweep.
LcpResult solvePgs(const LcpProblem& p, const PgsSettings& settings = {},
                   const Eigen::VectorXd* warm_start = nullptr);

}  // namespace tumble::lcp
