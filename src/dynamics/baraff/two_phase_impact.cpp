#include "dynamics/baraff/two_phase_impact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/baraff/impact_energy.h"
#include "dynamics/contact_rows.h"

namespace tumble {
namespace {

// Stronge's scale s: iterations at most, and the relative miss on the work at which it is found.
// The work grows about as s^2 (exactly so without friction, where the first guess is the answer).
// A restitution impulse 16 times Poisson's is far beyond any the laws give; the cap only bounds
// the search.
constexpr int kMaxScaleIterations = 60;
constexpr double kWorkTolerance = 1e-12;
constexpr double kMaxScale = 16;

}  // namespace

void applyTwoPhaseImpact(World& world, const std::vector<const Contact*>& points, const std::vector<double>& e,
                         RestitutionLaw law, bool friction, ContactSolveStats& stats) {
  ContactLcp lcp = buildContactLcp(world, points, std::vector<char>(points.size(), friction));
  lcp::LcpProblem& problem = lcp.problem;
  auto readVelocities = [&] {
    for (std::size_t r = 0; r < lcp.rows.size(); ++r) problem.b[r] = rowVelocity(world, lcp.rows[r]);
  };
  auto normal = [&](const Eigen::VectorXd& v, std::size_t i) { return v[lcp.normal_row[i]]; };
  // Compression: the inelastic impact from the velocities before.
  readVelocities();
  const Eigen::VectorXd before = problem.b;
  const lcp::LcpResult compressed = solveContactLcp(problem, stats);
  applyAlongRows(world, lcp.rows, compressed.f);
  readVelocities();
  std::vector<double> p_c;   // per point
  bool restitutes = false;
  double target = 0;   // J: the work restitution gives back (Stronge): e_i^2 of what each absorbed
  for (std::size_t i = 0; i < points.size(); ++i) {
    p_c.push_back(std::max(0.0, normal(compressed.f, i)));
    restitutes |= e[i] * p_c[i] > 0;
    target += e[i] * e[i] * -0.5 * p_c[i] * (normal(before, i) + normal(problem.b, i));
  }
  if (!restitutes) return;
  // Restitution from the velocities compression left (now in b), each normal impulse at least
  // s e_i p_c,i; returns the normal work it did.
  const ImpactMomenta after_compression(world, points);
  const Eigen::VectorXd between = problem.b;
  auto restitute = [&](double s) {
    after_compression.restore(world);
    for (std::size_t i = 0; i < points.size(); ++i) problem.lo[lcp.normal_row[i]] = s * e[i] * p_c[i];
    const lcp::LcpResult r = solveContactLcp(problem, stats);
    applyAlongRows(world, lcp.rows, r.f);
    double work = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      work += 0.5 * normal(r.f, i) * (normal(between, i) + normalVelocity(world, *points[i]));
    return work;
  };
  if (law == RestitutionLaw::Poisson || !(target > 0)) {
    restitute(law == RestitutionLaw::Poisson ? 1.0 : 0.0);
    return;
  }
  // Stronge: s from the work's growth as s^2, kept inside the bracket found so far (else halved).
  double lo = 0, hi = std::numeric_limits<double>::infinity(), s = 1;
  for (int i = 0; i < kMaxScaleIterations; ++i) {
    const double work = restitute(s);
    if (std::abs(work - target) <= kWorkTolerance * target) return;
    (work < target ? lo : hi) = s;
    double next = work > 0 ? s * std::sqrt(target / work) : 2 * s;
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * s;
    if (lo >= kMaxScale) break;
    s = std::min(next, kMaxScale);
  }
  restitute(lo);   // not settled: the largest scale known to give back no more than its share
}

}  // namespace tumble
