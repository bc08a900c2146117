#include "dynamics/lcp/dantzig_solver.h"

#include "dynamics/lcp/boxed_pivoting.h"
#include "dynamics/lcp/friction_fixed_point.h"

#include <algorithm>
#include <cmath>

namespace tumble::lcp {

namespace {

// Normal forces (and every other non-friction variable) first, then friction in index order: when
// a friction variable is driven, the normal force its bound comes from has already been settled
// (ODE's dLCP orders its unknowns the same way).
void processingOrder(const LcpProblem& p, std::vector<int>& order) {
  order.clear();
  for (int i = 0; i < p.size(); ++i)
    if (!p.isFriction(i)) order.push_back(i);
  for (int i = 0; i < p.size(); ++i)
    if (p.isFriction(i)) order.push_back(i);
}

// The buffers of a solve, kept per thread between solves.
struct Workspace {
  Eigen::VectorXd lo, hi, next_lo, next_hi;
  std::vector<int> order;
  std::vector<Bound> set, last_set;
  BoxedPivoting engine;
  std::vector<int> clamped;   // the last pass's clamped set: the next pass's first guess
};

bool hasFriction(const LcpProblem& p) {
  return std::any_of(p.friction_of.begin(), p.friction_of.end(), [](int k) { return k >= 0; });
}

// Whether the friction bounds newHi equal the ones used (hi) to friction_tolerance·(1 + max bound).
bool boundsConverged(const LcpProblem& p, const Eigen::VectorXd& hi, const Eigen::VectorXd& newHi,
                     double tol) {
  double change = 0, scale = 0;
  for (int i = 0; i < p.size(); ++i) {
    if (!p.isFriction(i)) continue;
    change = std::max(change, std::abs(newHi[i] - hi[i]));
    scale = std::max(scale, newHi[i]);
  }
  return change <= tol * (1.0 + scale);
}

void finish(const LcpProblem& p, const DantzigSettings& s, LcpResult& r) {
  r.w.noalias() = p.A * r.f;   // A f + b, the product first: no temporary
  r.w += p.b;
  r.residual = measureResidual(p, r.f, r.w);
  // The pivoting keeps w by updates, pivot after pivot, and judges each variable by that w. On
  // clamped sets near singular (a tower of crossed blocks: four coplanar corners on every face it
  // rests on) the updated w drifted from A f + b, and a pass ended "solved" with a normal row
  // approaching at 0.40 m/s beside rows pushing apart at 0.21 m/s: the answer launched the tower's
  // bottom block and the correction lifted the tower by 15 J. An answer is solved only if A f + b
  // says so.
  if (r.status == LcpStatus::Solved) {
    const double tol = s.solved_tolerance * termScale(p, r.f);
    if (!(std::max(r.residual.complementarity, r.residual.bounds) <= tol))
      r.status = LcpStatus::MaxIterations;
  }
}

// One boxed LCP with the bounds fixed, its variables driven in ws.order; adds its pivots to r. A
// `seeded` pass (a later friction pass) starts from the last pass's clamped set and forces
// (BoxedPivoting::seed): its bounds moved only as far as the normal forces did, and most of its
// variables stay where they were, where driving them all again from zero took 89 % of the pivots
// of a domino run.
LcpStatus solveFixedBounds(const LcpProblem& p, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                           const DantzigSettings& s, Workspace& ws, LcpResult& r, bool seeded) {
  if (seeded) ws.clamped = ws.engine.clamped();
  ws.engine.reset(p.A, p.b, lo, hi, s);
  if (seeded) ws.engine.seed(ws.clamped, r.f);
  const LcpStatus status = ws.engine.run(ws.order, s.max_pivots_per_variable * p.size() + 16);
  r.f = ws.engine.f();
  r.iterations += ws.engine.pivots();
  return status;
}

}  // namespace

// Friction bounds ±mu·f_n depend on the unknowns. Each pass solves the boxed LCP with the bounds
// frozen at the previous pass's normal forces (pass 0 has none: bounds [0, 0], the frictionless
// problem) — a fixed point f_n = F(mu·f_n). It stops when the bounds reproduce themselves, so the
// returned f satisfies the friction cone exactly at its own normal forces. In a fixed set of sliding
// contacts the map is affine with slope mu·(moment arm ratio) < 1 for contacts that do not tip, so
// the error shrinks geometrically; a cap turns a non-converging case into MaxIterations.
LcpResult solveDantzig(const LcpProblem& p, const DantzigSettings& s) {
  LcpResult r;
  solveDantzig(p, s, r);
  return r;
}

void solveDantzig(const LcpProblem& p, const DantzigSettings& s, LcpResult& r) {
  thread_local Workspace ws;
  r.status = LcpStatus::Failed;
  r.iterations = 0;
  r.friction_passes = 0;
  r.residual = {};
  r.f.setZero(p.b.size());
  if (*validate(p) != '\0') {
    r.w = p.b;
    return;
  }
  Eigen::VectorXd &lo = ws.lo, &hi = ws.hi;
  lo = p.lo;
  hi = p.hi;
  const bool friction = hasFriction(p);
  if (friction) effectiveBounds(p, r.f, lo, hi);  // f = 0: friction bounds [0, 0]
  processingOrder(p, ws.order);   // the same for every pass
  r.status = solveFixedBounds(p, lo, hi, s, ws, r, false);
  ws.last_set.clear();
  for (int pass = 1; friction && r.status == LcpStatus::Solved; ++pass) {
    Eigen::VectorXd &nlo = ws.next_lo, &nhi = ws.next_hi;
    effectiveBounds(p, r.f, nlo, nhi);
    if (boundsConverged(p, hi, nhi, s.friction_tolerance)) break;
    // Two passes with one active set: the rest of the passes would only converge geometrically
    // to the fixed point of that set, which one linear solve gives (friction_fixed_point.h).
    activeSet(r.f, lo, hi, ws.set);
    if (ws.set == ws.last_set) {
      if (std::optional<Eigen::VectorXd> exact = solveFrictionFixedPoint(p, ws.set, lo, hi)) {
        r.f = *exact;
        ++r.friction_passes;
        break;
      }
    }
    ws.last_set.swap(ws.set);
    if (pass > s.max_friction_passes) {
      r.status = LcpStatus::MaxIterations;
      break;
    }
    lo.swap(nlo);
    hi.swap(nhi);
    r.friction_passes = pass;
    r.status = solveFixedBounds(p, lo, hi, s, ws, r, s.seed_friction_passes);
  }
  finish(p, s, r);
}

}  // namespace tumble::lcp
