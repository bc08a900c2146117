#include "dynamics/lcp/clamped_factor.h"

#include <cmath>

namespace tumble::lcp {

void ClampedFactor::reset(int capacity) {
  L_.setZero(capacity, capacity);
  members_.clear();
  members_.reserve(capacity);
}

double ClampedFactor::schur(const Eigen::MatrixXd& A, int j, Eigen::VectorXd& y) const {
  const int k = size();
  y.resize(k);
  for (int r = 0; r < k; ++r) y[r] = A(members_[r], j);
  if (k > 0) L_.topLeftCorner(k, k).triangularView<Eigen::Lower>().solveInPlace(y);
  return A(j, j) - y.squaredNorm();
}

bool ClampedFactor::add(const Eigen::MatrixXd& A, int j, double rel_tol) {
  Eigen::VectorXd y;
  const double s = schur(A, j, y);
  if (!(s > rel_tol * A(j, j))) return false;
  const int k = size();
  L_.row(k).head(k) = y.transpose();
  L_(k, k) = std::sqrt(s);
  members_.push_back(j);
  return true;
}

void ClampedFactor::remove(int p) {
  const int k = size(), m = k - p - 1;
  // With L = [L11 0 0; l21ᵀ l22 0; L31 l32 L33], deleting row and column p of A_CC leaves
  // [L11 0; L31 L33] except that the trailing block must absorb the column l32 it loses:
  // L33' L33'ᵀ = L33 L33ᵀ + l32 l32ᵀ, a rank-1 update done with Givens-like rotations.
  Eigen::VectorXd x = L_.col(p).segment(p + 1, m);
  if (m > 0) {
    L_.block(p, 0, m, p) = L_.block(p + 1, 0, m, p).eval();
    L_.block(p, p, m, m) = L_.block(p + 1, p + 1, m, m).eval();
  }
  for (int c = 0; c < m; ++c) {
    const int q = p + c;
    const double lqq = L_(q, q);
    const double r = std::hypot(lqq, x[c]);
    const double cs = r / lqq, sn = x[c] / lqq;
    L_(q, q) = r;
    for (int i = c + 1; i < m; ++i) {
      const double lik = (L_(p + i, q) + sn * x[i]) / cs;
      x[i] = cs * x[i] - sn * lik;
      L_(p + i, q) = lik;
    }
  }
  members_.erase(members_.begin() + p);
}

void ClampedFactor::solveInPlace(Eigen::VectorXd& rhs) const {
  const int k = size();
  if (k == 0) return;
  const auto L = L_.topLeftCorner(k, k).triangularView<Eigen::Lower>();
  L.solveInPlace(rhs);
  L.transpose().solveInPlace(rhs);
}

void ClampedFactor::backSolve(Eigen::VectorXd& y) const {
  const int k = size();
  if (k > 0) L_.topLeftCorner(k, k).triangularView<Eigen::Lower>().transpose().solveInPlace(y);
  y = -y;
}

}  // namespace tumble::lcp
