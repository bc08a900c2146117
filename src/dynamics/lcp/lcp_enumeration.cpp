#include "dynamics/lcp/lcp_enumeration.h"

#include <cassert>

namespace tumble::lcp {

namespace {

// Solves the basis; returns false if A_CC f_C = −b_C is inconsistent.
bool solveBasis(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, unsigned mask, double tol,
                Eigen::VectorXd& f) {
  std::vector<int> C;
  for (int i = 0; i < b.size(); ++i)
    if (mask & (1u << i)) C.push_back(i);
  f = Eigen::VectorXd::Zero(b.size());
  if (C.empty()) return true;
  const Eigen::MatrixXd Acc = A(C, C);
  const Eigen::VectorXd rhs = -b(C);
  const Eigen::VectorXd fc = Acc.completeOrthogonalDecomposition().solve(rhs);
  if ((Acc * fc - rhs).lpNorm<Eigen::Infinity>() > tol) return false;
  f(C) = fc;
  return true;
}

}  // namespace

std::vector<EnumeratedSolution> enumerateLcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                             double tol) {
  const int n = static_cast<int>(b.size());
  assert(n <= 16);
  const double scale = b.lpNorm<Eigen::Infinity>() + A.cwiseAbs().rowwise().sum().maxCoeff();
  const double t = tol * scale;
  std::vector<EnumeratedSolution> out;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    EnumeratedSolution s;
    if (!solveBasis(A, b, mask, t, s.f)) continue;
    s.w = A * s.f + b;
    if (s.f.minCoeff() < -t || s.w.minCoeff() < -t) continue;
    s.basis = mask;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace tumble::lcp
