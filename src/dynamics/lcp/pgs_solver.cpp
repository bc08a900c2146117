#include "dynamics/lcp/pgs_solver.h"

#include <algorithm>
#include <cmath>

namespace tumble::lcp {

namespace {

double lowerBound(const LcpProblem& p, const Eigen::VectorXd& f, int i) {
  return p.isFriction(i) ? -p.mu[i] * std::max(0.0, f[p.friction_of[i]]) : p.lo[i];
}

double upperBound(const LcpProblem& p, const Eigen::VectorXd& f, int i) {
  return p.isFriction(i) ? p.mu[i] * std::max(0.0, f[p.friction_of[i]]) : p.hi[i];
}

// One sweep; returns the largest change in w units, max_i |Δf_i|·A_ii.
double sweep(const LcpProblem& p, double sor, Eigen::VectorXd& f) {
  double change = 0;
  for (int i = 0; i < p.size(); ++i) {
    const double aii = p.A(i, i);
    if (!(aii > 0)) continue;  // a variable that moves nothing cannot be chosen by this row
    const double wi = p.A.col(i).dot(f) + p.b[i];  // A symmetric: column i is row i
    const double fi = std::clamp(f[i] - sor * wi / aii, lowerBound(p, f, i), upperBound(p, f, i));
    change = std::max(change, std::abs(fi - f[i]) * aii);
    f[i] = fi;
  }
  return change;
}

}  // namespace

LcpResult solvePgs(const LcpProblem& p, const PgsSettings& s, const Eigen::VectorXd* warm_start) {
  LcpResult r;
  const int n = p.size();
  r.f = Eigen::VectorXd::Zero(n);
  if (*validate(p) != '\0') {
    r.w = p.b;
    return r;
  }
  if (warm_start && warm_start->size() == n) r.f = *warm_start;
  for (int i = 0; i < n; ++i)
    r.f[i] = std::clamp(r.f[i], lowerBound(p, r.f, i), upperBound(p, r.f, i));
  const double stop = s.tolerance * (p.b.lpNorm<Eigen::Infinity>() + 1e-300);
  r.status = LcpStatus::MaxIterations;
  while (r.iterations < s.max_iterations) {
    ++r.iterations;
    if (sweep(p, s.sor, r.f) <= stop) {
      r.status = LcpStatus::Solved;
      break;
    }
  }
  if (!r.f.allFinite()) r.status = LcpStatus::Failed;
  r.w = p.A * r.f + p.b;
  r.residual = measureResidual(p, r.f, r.w);
  return r;
}

}  // namespace tumble::lcp
