#include "dynamics/lcp/friction_fixed_point.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace tumble::lcp {

std::vector<Bound> activeSet(const Eigen::VectorXd& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  std::vector<Bound> set;
  activeSet(f, lo, hi, set);
  return set;
}

void activeSet(const Eigen::VectorXd& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, std::vector<Bound>& set) {
  set.assign(f.size(), Bound::Inside);
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const double eps = 1e-12 * (1 + std::max(std::abs(f[i]), 0.0));
    if (f[i] <= lo[i] + eps) set[i] = Bound::Lower;
    else if (f[i] >= hi[i] - eps) set[i] = Bound::Upper;
  }
}

std::optional<Eigen::VectorXd> solveFrictionFixedPoint(const LcpProblem& p, const std::vector<Bound>& set,
                                                       const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                                       double tolerance) {
  const int n = p.size();
  std::vector<int> index(n, -1), inside;
  for (int i = 0; i < n; ++i)
    if (set[i] == Bound::Inside) {
      index[i] = static_cast<int>(inside.size());
      inside.push_back(i);
    }
  const int m = static_cast<int>(inside.size());
  // A variable at a bound is a constant, or (friction whose normal is clamped) ±mu times it.
  Eigen::VectorXd constant = Eigen::VectorXd::Zero(n);
  std::vector<int> follows(n, -1);
  std::vector<double> slope(n, 0);
  for (int i = 0; i < n; ++i) {
    if (set[i] == Bound::Inside) continue;
    const double sign = set[i] == Bound::Upper ? 1 : -1;
    if (p.isFriction(i) && index[p.friction_of[i]] >= 0) {
      follows[i] = p.friction_of[i];
      slope[i] = sign * p.mu[i];
    } else if (p.isFriction(i)) {
      constant[i] = 0;   // its normal is at its bound (0): no friction
    } else {
      constant[i] = set[i] == Bound::Upper ? hi[i] : lo[i];
    }
  }
  Eigen::MatrixXd M(m, m);
  Eigen::VectorXd rhs(m);
  for (int r = 0; r < m; ++r) {
    const int i = inside[r];
    for (int c = 0; c < m; ++c) M(r, c) = p.A(i, inside[c]);
    rhs[r] = -p.b[i];
    for (int j = 0; j < n; ++j) {
      if (set[j] == Bound::Inside) continue;
      if (follows[j] >= 0) M(r, index[follows[j]]) += p.A(i, j) * slope[j];
      else rhs[r] -= p.A(i, j) * constant[j];
    }
  }
  Eigen::VectorXd x = m > 0 ? Eigen::VectorXd(M.completeOrthogonalDecomposition().solve(rhs)) : Eigen::VectorXd();
  Eigen::VectorXd f = constant;
  for (int r = 0; r < m; ++r) f[inside[r]] = x[r];
  for (int j = 0; j < n; ++j)
    if (follows[j] >= 0) f[j] = slope[j] * f[follows[j]];
  if (!f.allFinite()) return std::nullopt;
  const Eigen::VectorXd w = p.A * f + p.b;
  const double scale = termScale(p, f);
  const LcpResidual res = measureResidual(p, f, w);
  const double tol = tolerance * scale + 1e-300;
  if (res.bounds > tol || res.complementarity > tol) return std::nullopt;
  return f;
}

}  // namespace tumble::lcp
