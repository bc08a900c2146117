#include "dynamics/baraff/impulse_propagation.h"

#include <Eigen/QR>
#include <algorithm>
#include <limits>

#include "dynamics/baraff/impact_energy.h"
#include "dynamics/baraff/neighbour_turn_back.h"
#include "dynamics/baraff/restitution_laws.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/contact_rows.h"
#include "dynamics/island_impulses.h"
#include "dynamics/settings.h"

namespace tumble {
namespace {

// Newton's law on the points as an LCP in the impulses j:  w = A j + b  with b = (1 + e) v- on the
// normal rows (so w = v+ + e v- >= 0) and b = v_t on the friction rows (w = v_t+ = 0 while the
// impulse is inside the friction bound). Applies the impulses.
void applyNewtonImpulses(World& world, const std::vector<const Contact*>& points,
                         const std::vector<double>& vn, const std::vector<double>& e, double scale,
                         bool friction, ContactSolveStats& stats) {
  ContactLcp lcp = buildContactLcp(world, points, std::vector<char>(points.size(), friction));
  for (std::size_t r = 0; r < lcp.rows.size(); ++r) lcp.problem.b[r] = rowVelocity(world, lcp.rows[r]);
  for (std::size_t i = 0; i < points.size(); ++i)
    lcp.problem.b[lcp.normal_row[i]] = (1 + scale * e[i]) * vn[i];
  lcp::LcpResult r = solveContactLcp(lcp.problem, stats);
  applyAlongRows(world, lcp.rows, r.f);
}

// Newton's law with restitution on `points` (pre-impact normal velocities vn), never adding energy.
// Kane's paradox: with friction, Newton's law on velocities can return more energy than the impact
// took (the tangential impulse changes the normal velocity the restitution acts on). The inelastic
// solve (e = 0) cannot: with w = v+ and j the impulses, the energy change is j.w - j^T A j / 2,
// where j_n w_n = 0 by complementarity and j_t w_t <= 0 at a friction bound, so it is <= 0. Only
// an inexact friction solve can miss that; without friction rows the inelastic impulse is a
// projection (energy change -j^T A j / 2).
void newtonImpact(World& world, const std::vector<const Contact*>& points, const std::vector<double>& vn,
                  const BounceThreshold& min_bounce_speed, double restitution_scale, ContactSolveStats& stats) {
  std::vector<double> e;
  for (std::size_t i = 0; i < points.size(); ++i) e.push_back(vn[i] < -min_bounce_speed.along(points[i]->normal) ? points[i]->restitution : 0.0);
  applyAddingNoEnergy(
      world, points, restitution_scale,
      [&](double scale) { applyNewtonImpulses(world, points, vn, e, scale, true, stats); },
      [&] { applyNewtonImpulses(world, points, vn, e, 0, false, stats); });
}

// An impact whose lift-offs cannot last settles. Newton's law at a landing edge turns the body
// about that edge and lifts the edge it rested on (a rocking block: Housner 1963); that is right,
// and the rocking dies out by a constant factor per landing, but it never ends (a Zeno sequence,
// like a bouncing ball's): as the lift-offs shrink to the contact tolerance, each landing found
// within the tolerance starts the next, and a box on its face chattered for ever at about
// 5 mrad/s. So a lift-off is kept only if it lasts: gravity, with the points the impact did not
// lift held where they are, must not bring every lifted point back within `settle_within`
// seconds. That is a law of the motion, not of its scale: the rocking of a 5 cm block and of a
// 5 m one settles when its swings get shorter than the step can follow, and not before (a fixed
// speed below which impacts settled cut a 15 cm block's rocking short at its third landing).
// To settle, the touching points' normal velocities are set to max(v-, 0) by the least-norm
// normal impulses that do it; kept only if it adds no energy and leaves nothing approaching.
struct LiftOff {
  ContactRows normals;             // one normal row per point
  std::vector<double> target;      // per point: max(v-, 0), the most it may leave at
  std::vector<int> lifted, held;   // points leaving faster than their target, and the rest
  std::vector<ContactRow> holds;   // the held points' normal and (with friction) tangent rows
};

LiftOff measureLiftOff(const World& world, const std::vector<const Contact*>& points,
                       const std::vector<double>& vn, double slack) {
  LiftOff l;
  for (std::size_t i = 0; i < points.size(); ++i) {
    l.normals.addContact(world, *points[i], false);
    l.target.push_back(std::max(vn[i], 0.0));
    const bool lifted = rowVelocity(world, l.normals.rows.back()) - l.target.back() > slack;
    (lifted ? l.lifted : l.held).push_back(static_cast<int>(i));
  }
  ContactRows holds;
  for (int i : l.held) holds.addContact(world, *points[static_cast<std::size_t>(i)], true);
  l.holds = std::move(holds.rows);
  return l;
}

// Whether gravity brings every lifted point back within `within` seconds. For half of it gravity's
// impulse acts on the impact's bodies while the held points keep their velocities, normal and
// (where they have friction) tangential: the least-norm impulses along their rows that undo what
// gravity did to them. (Held only along the normal, a rocking block's pivot would slide and its
// lifted corner fall back several times too soon.) A lifted point that at the half no longer
// leaves faster than its target, slowing at least that fast, is back by the end.
// Bodies pressing on these from outside the impact, and spin's own accelerations, are left out:
// the answer decides only whether a lift-off is long enough to keep.
bool liftOffsShort(World& world, const std::vector<const Contact*>& points, const LiftOff& l, double within) {
  ImpactMomenta before(world, points);
  const std::vector<ContactRow>& held = l.holds;
  std::vector<double> held_was;
  for (const ContactRow& r : held) held_was.push_back(rowVelocity(world, r));
  for (int b : before.bodies) world.bodies[b].P += world.bodies[b].mass * world.gravity * (0.5 * within);
  if (!held.empty()) {
    Eigen::VectorXd undo(static_cast<Eigen::Index>(held.size()));
    for (std::size_t k = 0; k < held.size(); ++k)
      undo[static_cast<Eigen::Index>(k)] = held_was[k] - rowVelocity(world, held[k]);
    const Eigen::VectorXd f =
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(delassus(world, held)).solve(undo);
    if (f.allFinite()) applyAlongRows(world, held, f);
  }
  bool back = true;
  for (int i : l.lifted) {
    const std::size_t k = static_cast<std::size_t>(i);
    back &= rowVelocity(world, l.normals.rows[k]) <= l.target[k];
  }
  before.restore(world);
  return back;
}

void settleShortLiftOffs(World& world, const std::vector<const Contact*>& points, const std::vector<double>& vn,
                         const SettleRule& rule) {
  const LiftOff l = measureLiftOff(world, points, vn, rule.slack_m_s);
  if (l.lifted.empty() || !liftOffsShort(world, points, l, rule.within_s)) return;
  ImpactMomenta before(world, points);
  const double energy = before.energy(world);
  const std::vector<ContactRow>& rows = l.normals.rows;
  Eigen::VectorXd change(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k)
    change[static_cast<Eigen::Index>(k)] = l.target[k] - rowVelocity(world, rows[k]);
  const Eigen::VectorXd f = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(delassus(world, rows)).solve(change);
  if (!f.allFinite()) return;
  applyAlongRows(world, rows, f);
  bool approaching = false;
  for (const ContactRow& row : rows) approaching |= rowVelocity(world, row) < -rule.slack_m_s;
  if (approaching || before.energy(world) > energy * (1 + kEnergySlack)) before.restore(world);
}

// The inelastic impact of an island too large to pivot (a masonry arch of 101 stones: 1224 rows,
// whose dense pivoting took seconds per impact): the velocity-level impulse problem of the island
// (island_impulses.h) with no target, v+ >= 0 on the normals and friction holding the tangential
// velocity within its pyramid. Every Gauss-Seidel update and every subspace step it takes lowers
// the kinetic energy, so it adds none.
void inelasticIslandImpact(World& world, const std::vector<const Contact*>& island, ContactSolveStats& stats) {
  const ContactRows rows = buildContactRows(world, island);
  Eigen::VectorXd b(rows.size());
  for (int r = 0; r < rows.size(); ++r) b[r] = rowVelocity(world, rows.rows[r]);
  IslandImpulseSettings gs;
  gs.tolerance = tuning::kImpulseTolerance;
  const IslandImpulses solved = solveIslandImpulses(world, rows, island, b, {}, gs, stats);
  applyAlongRows(world, rows.rows, solved.p);
}

}  // namespace

void resolveImpact(World& world, const std::vector<const Contact*>& points, const BounceThreshold& min_bounce_speed,
                   double restitution_scale, RestitutionLaw law, ContactSolveStats& stats, const SettleRule* settle) {
  std::vector<double> vn;
  for (const Contact* c : points) vn.push_back(normalVelocity(world, *c));
  // Poisson's and Stronge's laws live in restitution_laws.h; Newton's, and an impact those cannot
  // follow to its end (a compression that never ends), is the LCP above.
  switch (law) {
    case RestitutionLaw::Poisson:
    case RestitutionLaw::Stronge:
      if (restitutionLawImpact(world, points, vn, law, min_bounce_speed, restitution_scale, stats)) break;
      [[fallthrough]];
    case RestitutionLaw::Newton:
      newtonImpact(world, points, vn, min_bounce_speed, restitution_scale, stats);
  }
  if (settle) settleShortLiftOffs(world, points, vn, *settle);
}

namespace {

// The contacts of one pair of bodies: one impact.
struct PairImpact {
  int a = -1, b = -1;
  std::vector<const Contact*> points;
  double approach = 0;   // m/s: the most negative normal velocity of its points
};

std::vector<PairImpact> groupByPair(const std::vector<const Contact*>& island) {
  std::vector<PairImpact> pairs;
  for (const Contact* c : island) {
    auto same = [&](const PairImpact& p) {
      return (p.a == c->a && p.b == c->b) || (p.a == c->b && p.b == c->a);
    };
    auto it = std::find_if(pairs.begin(), pairs.end(), same);
    if (it == pairs.end()) it = pairs.insert(pairs.end(), PairImpact{c->a, c->b, {}, 0});
    it->points.push_back(c);
  }
  return pairs;
}

double approachOf(const World& world, const PairImpact& p) {
  double v = std::numeric_limits<double>::infinity();
  for (const Contact* c : p.points) v = std::min(v, normalVelocity(world, *c));
  return v;
}

bool sharesMovingBody(const World& world, const PairImpact& p, const PairImpact& q) {
  for (int x : {p.a, p.b})
    if (!world.bodies[x].is_static && (x == q.a || x == q.b)) return true;
  return false;
}

// Whether any point of the island approaches fast enough to bounce (restitution_laws.h's rule).
bool anyBounces(const World& world, const std::vector<const Contact*>& island, const BounceThreshold& min_bounce_speed) {
  for (const Contact* c : island)
    if (c->restitution > 0 && normalVelocity(world, *c) < -min_bounce_speed.along(c->normal)) return true;
  return false;
}

}  // namespace

void plasticImpact(World& world, const std::vector<const Contact*>& island, const ContactSettings& s,
                   const BounceThreshold& min_bounce_speed, const SettleRule& settle, ContactSolveStats& stats) {
  if (tooLargeToPivot(island.size(), s.max_direct_rows)) inelasticIslandImpact(world, island, stats);
  else resolveImpact(world, island, min_bounce_speed, 0.0, s.restitution_law, stats, &settle);
}

void plasticIslandImpact(World& world, const std::vector<const Contact*>& island, const ContactSettings& s,
                         const BounceThreshold& min_bounce_speed, double dt, ContactSolveStats& stats) {
  plasticImpact(world, island, s, min_bounce_speed, settleRule(s, dt), stats);
}

void propagateImpulses(World& world, const std::vector<const Contact*>& island,
                       const std::vector<const Contact*>& outside, const ContactSettings& s,
                       const BounceThreshold& min_bounce_speed, double dt, ContactSolveStats& stats) {
  const SettleRule settle = settleRule(s, dt);
  // Pair by pair is how an elastic impact travels (a cradle's balls leave one after another). An
  // island where no point bounces is a plastic impact, whose answer is the simultaneous one: every
  // point's impulse at once, no point approaching after (J.-J. Moreau's impact law). Pair by pair it
  // is a Gauss-Seidel sweep that friction keeps from converging to it: a tent landing on a loose
  // card took its feet's impulses first, card and ground apart, and spun its two cards unequally.
  if (!anyBounces(world, island, min_bounce_speed)) {
    plasticImpact(world, island, s, min_bounce_speed, settle, stats);
    return;
  }
  std::vector<PairImpact> pairs = groupByPair(island);
  for (PairImpact& p : pairs) p.approach = approachOf(world, p);
  const int n = static_cast<int>(pairs.size());
  // A chain of n pairs needs n rounds; a wave reflected back and forth a few more. Elastic rounds
  // are capped so a pinched body cannot bounce for ever; inelastic rounds converge like
  // Gauss-Seidel on the inelastic impulse LCP, and the cap only stops a slow one.
  const int elastic_rounds = 4 * n + 4, max_rounds = 16 * n + 16;
  const ContactNeighbours neighbours(world, island, outside);
  for (int round = 0; round < max_rounds; ++round) {
    // The pair approaching fastest (first in island order on ties: deterministic).
    int k = 0;
    for (int i = 1; i < n; ++i)
      if (pairs[i].approach < pairs[k].approach) k = i;
    if (pairs[k].approach >= -s.resting_speed_m_s) return;
    // An elastic pair impact whose lift-off a neighbour would turn back at once takes that
    // neighbour in (neighbour_turn_back.h); an inelastic one lifts nothing off.
    bool grown = false;
    if (round < elastic_rounds)
      grown = resolveImpactWithNeighbours(world, pairs[k].points, neighbours.around(world, pairs[k].points), s,
                                          min_bounce_speed, 1.0, settle, stats);
    else
      resolveImpact(world, pairs[k].points, min_bounce_speed, 0.0, s.restitution_law, stats, &settle);
    // A grown impact moved bodies beyond the pair's.
    for (PairImpact& p : pairs)
      if (grown || sharesMovingBody(world, pairs[k], p)) p.approach = approachOf(world, p);
  }
  // Not settled within the cap: all the island's contacts at once, inelastic. This leaves no
  // contact approaching, and adds no energy.
  plasticImpact(world, island, s, min_bounce_speed, settle, stats);
}

}  // namespace tumble
