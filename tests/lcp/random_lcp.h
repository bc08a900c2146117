// Test helper: random LCPs with a known solvable structure, from fixed seeds.
#pragma once

#include "dynamics/lcp/lcp_problem.h"

#include <random>

namespace tumble::lcp::test {

// A = MᵀM with M rank×n (rank < n: PSD, singular) plus shift·I; entries of M uniform in [−1, 1].
Eigen::MatrixXd randomPsd(int n, int rank, double shift, std::mt19937& rng);

// Entries uniform in [−scale, scale].
Eigen::VectorXd randomVector(int n, double scale, std::mt19937& rng);

// b = w* − A f* for a random complementary pair f*, w* ≥ 0 (each index has f* = 0 or w* = 0, about
// half each): the LCP is solvable even when A is singular.
Eigen::VectorXd solvableRhs(const Eigen::MatrixXd& A, std::mt19937& rng);

}  // namespace tumble::lcp::test
