#include "dynamics/baraff/drift_correction.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "dynamics/baraff/energy_payment.h"
#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"
#include "dynamics/island_projection.h"
#include "dynamics/position_projection.h"

namespace tumble {
namespace {

struct Pose {
  Eigen::Vector3d x;
  Eigen::Quaterniond q;
};

// A projection moves positions only, and may still raise the pair's energy: a lift adds potential
// energy, a turn changes the kinetic energy of the same angular momentum. Drift that took energy
// (a resting body sinking) is given it back; but drift that took none, a landing the sub-step
// could not time found a few mm deep, was lifted out on top of the speed it fell with: a tumbling
// block of the knockdown scene gained 0.02-0.04 J a sub-step, 0.12 J in 7 steps (1e-3 of the
// energy in play). The gain is paid from the pair's kinetic energy, as far as it goes, and what is
// left from the rest of the bodies touching it, directly or through others (its island): their
// momenta are scaled by one factor, which keeps their directions and the sign of every relative
// velocity between them. The island too, not the pair alone: a block at rest on the ground, under
// a stack a heavy ball had just landed on, had no kinetic energy to pay its lifts with, and eight
// passes lifting it out of the ground added 19 J in one step (the ball rolling on top had 1500 J).
// The price: where a resting body's drift took the energy its lift returns, and bodies moving
// against it pay for the lift anyway, the island loses m g times the drift (microjoules for a
// drift of the contact tolerance); a passive scene never gains energy this way (energy_payment.h).
//
// `island_of` gives the moving bodies touching a body (found only when the pair cannot pay).
template <typename IslandOf>
void payForProjection(World& world, int a, int b, double energy_before, IslandOf&& island_of) {
  const double gain = mechanicalEnergy(world, a) + mechanicalEnergy(world, b) - energy_before;
  if (!(gain > 0)) return;
  const double left = payFrom(world, {a, b}, gain);
  if (!(left > 0)) return;
  std::vector<int> others;
  for (int body : island_of(world.bodies[a].is_static ? b : a))
    if (body != a && body != b) others.push_back(body);
  payFrom(world, others, left);
}

// The moving bodies of each island of touching contacts, and each body's island (-1: none).
struct Islands {
  std::vector<std::vector<int>> members;
  std::vector<int> of;
};

Islands touchingIslands(const World& world, const std::vector<Contact>& contacts, double tol) {
  std::vector<const Contact*> touching;
  for (const Contact& c : contacts)
    if (c.depth >= -tol) touching.push_back(&c);
  Islands out;
  out.of.assign(world.bodies.size(), -1);
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, touching)) {
    std::vector<int>& members = out.members.emplace_back();
    for (const Contact* c : island)
      for (int body : {c->a, c->b})
        if (!world.bodies[body].is_static && out.of[body] < 0) {
          out.of[body] = static_cast<int>(out.members.size() - 1);
          members.push_back(body);
        }
  }
  return out;
}

// How far a body's points moved at most from `before` to `after` (r: the body's radius).
double pointsMoved(const Pose& before, const RigidBody& after, double r) {
  const double turn = 2 * std::acos(std::min(1.0, std::abs(before.q.dot(after.q))));
  return (after.x - before.x).norm() + 2 * r * std::sin(0.5 * turn);
}

}  // namespace

void DriftCorrection::startStep(const World& world) { used_.assign(world.bodies.size(), 0.0); }

CorrectionCount DriftCorrection::correct(World& world, const std::vector<Contact>& contacts, double tol,
                                         const std::vector<BodyExtent>& extents) {
  // Once per pair of bodies, all its points together: the four corners of a face resting too deep
  // share one depth and are lifted together, and a landing edge is lifted by turning about the
  // resting one rather than by lifting both.
  const BodyPairGroups grouped = groupByBodyPair(contacts);
  std::optional<Islands> islands;   // found the first time a pair cannot pay for its projection
  auto island_of = [&](int body) -> const std::vector<int>& {
    if (!islands) islands = touchingIslands(world, contacts, tol);
    return islands->members[static_cast<std::size_t>(islands->of[body])];   // a projected pair touches
  };
  struct Push {
    std::size_t first_seen, group;
  };
  std::vector<Push> pushes;
  for (std::size_t g = 0; g < grouped.groups.size(); ++g) {
    const auto& [begin, end] = grouped.groups[g];
    std::size_t first = SIZE_MAX;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = grouped.order[k];
      if (contacts[i].depth > tol) first = std::min(first, i);
    }
    if (first != SIZE_MAX) pushes.push_back({first, g});
  }
  // Pairs are projected in the order their first too-deep point was detected (deterministic).
  std::sort(pushes.begin(), pushes.end(), [](const Push& x, const Push& y) { return x.first_seen < y.first_seen; });
  std::vector<const Contact*> points;
  CorrectionCount count;
  for (const Push& p : pushes) {
    const auto& [begin, end] = grouped.groups[p.group];
    points.clear();
    for (std::size_t k = begin; k < end; ++k) points.push_back(&contacts[grouped.order[k]]);
    const int a = points.front()->a, b = points.front()->b;
    const Pose before_a{world.bodies[a].x, world.bodies[a].q}, before_b{world.bodies[b].x, world.bodies[b].q};
    const double energy_before = mechanicalEnergy(world, a) + mechanicalEnergy(world, b);
    if (!projectPair(world, points, tol, extents)) continue;
    const double moved_a = pointsMoved(before_a, world.bodies[a], extents[a].radius);
    const double moved_b = pointsMoved(before_b, world.bodies[b], extents[b].radius);
    // The reach: half the thinnest piece, FaultSettings::depth_share of it.
    if (used_[a] + moved_a > 0.5 * extents[a].thinnest || used_[b] + moved_b > 0.5 * extents[b].thinnest) {
      world.bodies[a].x = before_a.x, world.bodies[a].q = before_a.q;
      world.bodies[b].x = before_b.x, world.bodies[b].q = before_b.q;
      ++count.capped;
      continue;
    }
    used_[a] += moved_a;
    used_[b] += moved_b;
    payForProjection(world, a, b, energy_before, island_of);
    ++count.moved;
  }
  return count;
}

CorrectionCount DriftCorrection::correctIslands(World& world, const std::vector<Contact>& contacts, double tol,
                                                const std::vector<BodyExtent>& extents, int max_direct_rows,
                                                ContactSolveStats& stats) {
  // Every contact in hand, touching or within the detection margin: a push may close a gap, and
  // the gaps' rows keep it from driving a body into a neighbour it did not touch (a plate lifted
  // out of the block it landed in, into the block a millimetre above it).
  near_.clear();
  for (const Contact& c : contacts) near_.push_back(&c);
  ContactIslands& islands = islands_;
  islands.split(world, near_);
  CorrectionCount count;
  for (std::size_t k = 0; k < islands.size(); ++k) {
    const std::span<const Contact* const> island = islands[k];
    bool deep = false;
    for (const Contact* c : island) deep |= c->depth > tol;
    if (!deep) continue;
    const bool solved = tooLargeToPivot(island.size(), max_direct_rows)
                            ? islandProjectionBySweeps(world, island, tol, moves_, stats)
                            : islandProjection(world, island, tol, moves_, stats);
    if (!solved || moves_.empty()) continue;
    // The reach (as a pair's projection): half each body's thinnest piece over the step.
    bool within = true;
    for (const BodyDisplacement& d : moves_) {
      const double moved = d.dx.norm() + d.dtheta.norm() * extents[d.body].radius;
      within &= used_[d.body] + moved <= 0.5 * extents[d.body].thinnest;
    }
    if (!within) {
      ++count.capped;
      continue;
    }
    moved_bodies_.clear();
    double energy_before = 0;
    for (const BodyDisplacement& d : moves_) {
      moved_bodies_.push_back(d.body);
      energy_before += mechanicalEnergy(world, d.body);
    }
    double energy_after = 0;
    for (const BodyDisplacement& d : moves_) {
      used_[d.body] += d.dx.norm() + d.dtheta.norm() * extents[d.body].radius;
      displaceBody(world.bodies[d.body], d.dx, d.dtheta);
      energy_after += mechanicalEnergy(world, d.body);
    }
    // A lift out of drift that took no energy is paid for by the island's own kinetic energy.
    if (energy_after > energy_before) payFrom(world, moved_bodies_, energy_after - energy_before);
    ++count.moved;
  }
  return count;
}

}  // namespace tumble
