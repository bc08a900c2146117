// Test oracle: brute-force solution of a plain LCP (w = A f + b ≥ 0, f ≥ 0, wᵀf = 0) by trying all
// 2ⁿ complementary bases. Basis C (a bit mask) means f_C solves A_CC f_C = −b_C and f = 0 elsewhere;
// it is a solution when f_C ≥ 0 and w = A f + b ≥ 0 within the tolerance. A singular A_CC is solved
// in the least-squares sense (complete orthogonal decomposition) and kept only if consistent.
// Every LCP with a solution has one at a basis whose columns are independent, so the list is never
// empty when a solution exists. For A PSD, w is the same for every solution; f is unique for A PD.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace tumble::lcp {

struct EnumeratedSolution {
  Eigen::VectorXd f, w;
  unsigned basis = 0;  // bit i set: f_i is free (w_i = 0)
};

// n ≤ 16 (10 is the intended limit: 1024 small solves). tol, relative to ‖b‖∞ + ‖A‖∞, accepts a
// basis; keep it near rounding: 1e-9 admits near-solutions (w ≈ −1e-9) of nearly singular bases.
std::vector<EnumeratedSolution> enumerateLcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                             double tol = 1e-12);

}  // namespace tumble::lcp
