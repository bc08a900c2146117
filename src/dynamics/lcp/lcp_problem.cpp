#include "dynamics/lcp/lcp_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::lcp {

LcpProblem LcpProblem::plain(Eigen::MatrixXd A, Eigen::VectorXd b) {
  LcpProblem p;
  const Eigen::Index n = b.size();
  p.A = std::move(A);
  p.b = std::move(b);
  p.lo = Eigen::VectorXd::Zero(n);
  p.hi = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  return p;
}

const char* toString(LcpStatus status) {
  switch (status) {
    case LcpStatus::Solved: return "solved";
    case LcpStatus::MaxIterations: return "max-iterations";
    case LcpStatus::Failed: return "failed";
  }
  return "?";
}

void effectiveBounds(const LcpProblem& p, const Eigen::VectorXd& f, Eigen::VectorXd& lo,
                     Eigen::VectorXd& hi) {
  lo = p.lo;
  hi = p.hi;
  for (int i = 0; i < p.size(); ++i) {
    if (!p.isFriction(i)) continue;
    // a negative normal force (only possible in a non-converged iterate) gives no friction
    const double bound = p.mu[i] * std::max(0.0, f[p.friction_of[i]]);
    lo[i] = -bound;
    hi[i] = bound;
  }
}

LcpResidual measureResidual(const LcpProblem& p, const Eigen::VectorXd& f, const Eigen::VectorXd& w) {
  thread_local Eigen::VectorXd lo, hi;   // kept: a warm step's solves allocate nothing
  effectiveBounds(p, f, lo, hi);
  LcpResidual r;
  for (int i = 0; i < p.size(); ++i) {
    const double below = lo[i] - f[i], above = f[i] - hi[i];
    r.bounds = std::max({r.bounds, below, above});
    double v = 0;
    if (w[i] > 0) v = std::min(f[i] - lo[i], w[i]);
    if (w[i] < 0) v = std::min(hi[i] - f[i], -w[i]);
    r.complementarity = std::max(r.complementarity, std::abs(v));
  }
  return r;
}

double termScale(const LcpProblem& p, const Eigen::VectorXd& f) {
  double terms = 0;   // by rows: no temporary vector
  for (Eigen::Index i = 0; i < p.A.rows(); ++i) terms = std::max(terms, p.A.row(i).cwiseAbs().dot(f.cwiseAbs()));
  return p.b.lpNorm<Eigen::Infinity>() + terms + f.lpNorm<Eigen::Infinity>();
}

const char* validate(const LcpProblem& p) {
  const Eigen::Index n = p.b.size();
  if (p.A.rows() != n || p.A.cols() != n) return "A is not n×n with n = size of b";
  if (p.lo.size() != n || p.hi.size() != n) return "lo/hi do not have the size of b";
  if (!p.A.allFinite() || !p.b.allFinite()) return "A or b has a NaN or infinite entry";
  if (!p.friction_of.empty() && static_cast<Eigen::Index>(p.friction_of.size()) != n)
    return "friction_of is neither empty nor of size n";
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::isnan(p.lo[i]) || std::isnan(p.hi[i]) || p.lo[i] > p.hi[i]) return "lo > hi or NaN bound";
    if (p.friction_of.empty() || p.friction_of[i] < 0) continue;
    const int k = p.friction_of[i];
    if (k >= n || p.isFriction(k)) return "friction_of names a variable that is not a normal force";
    if (p.mu.size() != n || !(p.mu[i] >= 0)) return "mu missing or negative for a friction variable";
  }
  return "";
}

}  // namespace tumble::lcp
