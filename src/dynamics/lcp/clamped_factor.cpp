#include "dynamics/lcp/clamped_factor.h"

#include <cmath>

namespace tumble::lcp {

void ClampedFactor::reset(int capacity) {
  L_.setZero(capacity, capacity);
  members_.clear();
  members_.reserve(capacity);
  y_.resize(capacity);
  x_.resize(capacity);
}

double ClampedFactor::schur(const Eigen::MatrixXd& A, int j, Eigen::VectorXd& y) const {
  const int k = size();
  auto yk = y.head(k);
  for (int r = 0; r < k; ++r) yk[r] = A(members_[r], j);
  if (k > 0) L_.topLeftCorner(k, k).triangularView<Eigen::Lower>().solveInPlace(yk);
  return A(j, j) - yk.squaredNorm();
}

bool ClampedFactor::add(const Eigen::MatrixXd& A, int j, double rel_tol) {
  const double s = schur(A, j, y_);
  if (!(s > rel_tol * A(j, j))) return false;
  const int k = size();
  L_.row(k).head(k) = y_.head(k).transpose();
  L_(k, k) = std::sqrt(s);
  members_.push_back(j);
  return true;
}

void ClampedFactor::remove(int p) {
  const int k = size(), m = k - p - 1;
  // With L = [L11 0 0; l21ᵀ l22 0; L31 l32 L33], deleting row and column p of A_CC leaves
  // [L11 0; L31 L33] except that the trailing block must absorb the column l32 it loses:
  // L33' L33'ᵀ = L33 L33ᵀ + l32 l32ᵀ, a rank-1 update done with Givens-like rotations.
  auto x = x_.head(m);
  x = L_.col(p).segment(p + 1, m);
  // Rows p+1.. move up one (and, right of column p, left one), entry by entry in increasing order,
  // so that each source is read before it is overwritten; no temporary copy of the blocks.
  for (int c = 0; c < p; ++c)
    for (int r = p; r < p + m; ++r) L_(r, c) = L_(r + 1, c);
  for (int c = p; c < p + m; ++c)
    for (int r = p; r < p + m; ++r) L_(r, c) = L_(r + 1, c + 1);
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

void ClampedFactor::solveInPlace(Eigen::Ref<Eigen::VectorXd> rhs) const {
  const int k = size();
  if (k == 0) return;
  const auto L = L_.topLeftCorner(k, k).triangularView<Eigen::Lower>();
  L.solveInPlace(rhs);
  L.transpose().solveInPlace(rhs);
}

void ClampedFactor::backSolve(Eigen::VectorXd& y) const {
  const int k = size();
  auto yk = y.head(k);
  if (k > 0) L_.topLeftCorner(k, k).triangularView<Eigen::Lower>().transpose().solveInPlace(yk);
  yk = -yk;
}

}  // namespace tumble::lcp
