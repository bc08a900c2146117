#include "dynamics/baraff/neighbour_turn_back.h"

#include <algorithm>

#include "dynamics/baraff/impact_energy.h"
#include "dynamics/contact_rows.h"
#include "dynamics/settings.h"

namespace tumble {
namespace {

// How many times an impact may grow: each growth solves it again, and a stack of alternating
// plates and blocks grows by one pair of contacts a time.
constexpr int kMaxGrowths = 8;

bool contains(const std::vector<const Contact*>& set, const Contact* c) {
  return std::find(set.begin(), set.end(), c) != set.end();
}

// The neighbours that would close on the impact's bodies at once: touching and approaching, or
// apart by less than they close in `within_s`.
std::vector<const Contact*> closing(const World& world, const std::vector<const Contact*>& neighbours,
                                    const std::vector<const Contact*>& set, const ContactSettings& s,
                                    double within_s, double slack) {
  std::vector<const Contact*> out;
  for (const Contact* c : neighbours) {
    if (contains(set, c)) continue;
    const double vn = normalVelocity(world, *c);
    if (vn >= -slack) continue;
    if (c->depth >= -s.tolerance_m || -c->depth <= -vn * within_s) out.push_back(c);
  }
  return out;
}

// Whether stopping `close` plastically would bring back a point of `set` that the impact just
// lifted (faster than max(v-, 0)). Leaves the world as it was.
bool turnsBack(World& world, const std::vector<const Contact*>& set, const std::vector<double>& vn_before,
               const std::vector<const Contact*>& close, const BounceThreshold& min_bounce_speed, RestitutionLaw law,
               double slack, ContactSolveStats& stats) {
  std::vector<std::size_t> lifted;
  for (std::size_t i = 0; i < set.size(); ++i)
    if (normalVelocity(world, *set[i]) > std::max(vn_before[i], 0.0) + slack) lifted.push_back(i);
  if (lifted.empty()) return false;
  std::vector<const Contact*> touched = set;
  touched.insert(touched.end(), close.begin(), close.end());
  const ImpactMomenta before(world, touched);
  resolveImpact(world, close, min_bounce_speed, 0.0, law, stats);
  bool back = false;
  for (std::size_t i : lifted) back |= normalVelocity(world, *set[i]) <= std::max(vn_before[i], 0.0) + slack;
  before.restore(world);
  return back;
}

}  // namespace

ContactNeighbours::ContactNeighbours(const World& world, const std::vector<const Contact*>& island,
                                     const std::vector<const Contact*>& outside)
    : by_body_(world.bodies.size()) {
  for (const auto* list : {&island, &outside})
    for (const Contact* c : *list)
      for (int b : {c->a, c->b})
        if (!world.bodies[b].is_static) by_body_[b].push_back(c);
}

std::vector<const Contact*> ContactNeighbours::around(const World& world,
                                                      const std::vector<const Contact*>& points) const {
  std::vector<const Contact*> out;
  for (const Contact* p : points)
    for (int b : {p->a, p->b}) {
      if (world.bodies[b].is_static) continue;
      for (const Contact* c : by_body_[b])
        if (!contains(points, c) && !contains(out, c)) out.push_back(c);
    }
  return out;
}

bool resolveImpactWithNeighbours(World& world, const std::vector<const Contact*>& points,
                                 const std::vector<const Contact*>& neighbours, const ContactSettings& s,
                                 const BounceThreshold& min_bounce_speed, double restitution_scale, const SettleRule& settle,
                                 ContactSolveStats& stats) {
  if (neighbours.empty()) {
    resolveImpact(world, points, min_bounce_speed, restitution_scale, s.restitution_law, stats, &settle);
    return false;
  }
  std::vector<const Contact*> all = points;
  all.insert(all.end(), neighbours.begin(), neighbours.end());
  const ImpactMomenta start(world, all);
  std::vector<const Contact*> set = points;
  std::vector<double> vn_before;
  for (const Contact* c : set) vn_before.push_back(normalVelocity(world, *c));
  for (int growth = 0;; ++growth) {
    resolveImpact(world, set, min_bounce_speed, restitution_scale, s.restitution_law, stats, &settle);
    if (growth == kMaxGrowths) return true;
    // Which neighbours close is judged on the velocities the impact left, from where it started.
    const std::vector<const Contact*> close =
        closing(world, neighbours, set, s, settle.within_s, settle.slack_m_s);
    if (close.empty() ||
        !turnsBack(world, set, vn_before, close, min_bounce_speed, s.restitution_law, settle.slack_m_s, stats))
      return growth > 0;
    start.restore(world);
    for (const Contact* c : close) {
      set.push_back(c);
      vn_before.push_back(normalVelocity(world, *c));
    }
    ++stats.merged_impacts;
  }
}

}  // namespace tumble
