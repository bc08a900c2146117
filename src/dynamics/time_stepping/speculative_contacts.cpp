#include "dynamics/time_stepping/speculative_contacts.h"

#include <algorithm>
#include <cmath>

#include "collision/first_touch.h"
#include "collision/narrow_phase.h"
#include "dynamics/parallel_for.h"

namespace tumble {

namespace {

// The largest turn (rad) between the instants at which a swept pair's overlap is looked for, and
// the most instants in a step: a piece turning 0.26 rad in a step is looked at every 0.05 rad.
constexpr double kSweptSampleTurn = 0.05;
constexpr int kMaxSweptSamples = 16;

FreeMotion freeMotion(const World& world, const RigidBody& body, double dt, bool gravity) {
  FreeMotion m;
  m.pose = poseOf(body);
  if (body.is_static) return m;
  // The velocity the body integrates with when no contact acts: gravity's impulse comes first.
  m.velocity = body.velocity() + (gravity ? Eigen::Vector3d(world.gravity * dt) : Eigen::Vector3d::Zero());
  m.spin = body.angularVelocity();
  return m;
}

// A point of a body at time t of its free motion, carried back to where it is now.
Eigen::Vector3d backToStart(const FreeMotion& m, double t, const Eigen::Vector3d& p) {
  return m.pose * (m.at(t).inverse(Eigen::Isometry) * p);
}

}  // namespace

long keepReachableContacts(const World& world, const ContactDetector& detector, std::vector<Contact>& contacts,
                           std::vector<PiecePair>& pairs, double dt, bool gravity, double tolerance) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact c = contacts[i];
    const PiecePair pair = pairs[i];
    if (c.closest_points && pair.piece_b >= 0 && -c.depth > tolerance) {
      // a pair apart along parallel edges has a point at each end: one first touch for the pair
      if (i > 0 && pairs[i - 1] == pair && contacts[i - 1].closest_points) continue;
      const FreeMotion ma = freeMotion(world, world.bodies[c.a], dt, gravity);
      const FreeMotion mb = freeMotion(world, world.bodies[c.b], dt, gravity);
      const FirstTouch touch = firstTouch(detector.hull(pair.piece_a), ma, detector.hull(pair.piece_b), mb, dt, tolerance);
      if (!touch.touches) continue;
      const Eigen::Vector3d pa = backToStart(ma, touch.time, touch.point_a);
      const Eigen::Vector3d pb = backToStart(mb, touch.time, touch.point_b);
      c.normal = touch.normal;
      c.point = 0.5 * (pa + pb);
      c.depth = -std::max(touch.normal.dot(pb - pa), 0.0);
    }
    contacts[kept] = c;
    pairs[kept] = pair;
    ++kept;
  }
  const long dropped = static_cast<long>(contacts.size() - kept);
  contacts.resize(kept);
  pairs.resize(kept);
  return dropped;
}

long addSweptContacts(const World& world, const ContactDetector& detector, std::vector<Contact>& contacts,
                      std::vector<PiecePair>& pairs, const std::vector<Eigen::Vector3d>& spin, double dt, bool gravity,
                      double margin, double tolerance, int threads) {
  const std::size_t found = contacts.size();
  // Each pair of pieces once, and only pairs turning fast enough to matter; then each pair's swept
  // contacts on the threads, appended in the pairs' order. The lists are kept between steps (per
  // calling thread; a job's manifold per worker thread), so a warm step allocates nothing here.
  thread_local std::vector<std::size_t> own_firsts;
  thread_local std::vector<std::vector<Contact>> own_swept;
  // Named by reference: inside the jobs a thread_local's name would be the worker's own.
  std::vector<std::size_t>& firsts = own_firsts;
  std::vector<std::vector<Contact>>& swept = own_swept;
  firsts.clear();
  for (std::size_t i = 0; i < found; ++i) {
    const PiecePair pair = pairs[i];
    if (pair.piece_b < 0 || (i > 0 && pairs[i - 1] == pair)) continue;
    const double spin_a = spin[static_cast<std::size_t>(contacts[i].a)].norm();
    const double spin_b = spin[static_cast<std::size_t>(contacts[i].b)].norm();
    if ((spin_a * detector.hull(pair.piece_a).radius + spin_b * detector.hull(pair.piece_b).radius) * dt <= margin)
      continue;
    firsts.push_back(i);
  }
  if (swept.size() < firsts.size()) swept.resize(firsts.size());
  for (std::size_t job = 0; job < firsts.size(); ++job) swept[job].clear();
  parallelFor(threads, firsts.size(), [&](std::size_t job) {
    const std::size_t i = firsts[job];
    const PiecePair pair = pairs[i];
    const Contact& first = contacts[i];
    const CollisionHull& ha = detector.hull(pair.piece_a);
    const CollisionHull& hb = detector.hull(pair.piece_b);
    const FreeMotion ma = freeMotion(world, world.bodies[first.a], dt, gravity);
    const FreeMotion mb = freeMotion(world, world.bodies[first.b], dt, gravity);
    SatCache cache;
    thread_local ContactManifold m;
    // The pair where its free motion has taken it at time t; each point deeper than the tolerance,
    // carried back to the start, becomes a contact unless the pair holds one near it. Returns
    // whether a point was deep but lies behind the normal found at t (below).
    auto collideAt = [&](double t) {
      bool behind = false;
      const std::size_t earlier = swept[job].size();   // from another instant: not to be repeated
      if (!collide(ha, ma.at(t), hb, mb.at(t), 0.0, cache, m)) return behind;
      for (const ContactPoint& p : m.points) {
        if (p.depth <= tolerance) continue;
        const Eigen::Vector3d pa = backToStart(ma, t, p.position + 0.5 * p.depth * m.normal);
        const Eigen::Vector3d pb = backToStart(mb, t, p.position - 0.5 * p.depth * m.normal);
        const double gap = m.normal.dot(pb - pa);
        if (gap <= tolerance) {
          behind = true;
          continue;
        }
        const Eigen::Vector3d at = 0.5 * (pa + pb);
        bool known = false;
        for (std::size_t k = i; k < found && pairs[k] == pair; ++k)
          known = known || (contacts[k].point - at).norm() < 0.05 * std::min(ha.size, hb.size);
        for (std::size_t k = 0; k < earlier; ++k)
          known = known || (swept[job][k].point - at).norm() < 0.05 * std::min(ha.size, hb.size);
        if (known) continue;
        Contact c = first;
        c.point = at;
        c.normal = m.normal;
        c.depth = -gap;
        c.closest_points = false;
        swept[job].push_back(c);
      }
      return behind;
    };
    // Where the pieces end the step deep in each other, the separating direction there need not be
    // the one they came in along: a shard spinning at 60 rad/s swings a corner 15 degrees into its
    // neighbour, and the overlap at the end is shallowest straight up, behind which the corner
    // started. A row along it would ask the corner to jump back 4 cm in one step, and none is
    // made. The overlap is then looked for at earlier instants of the motion, each a turn of at
    // most kSweptSampleTurn after the last, and the first instant that shows one gives the rows:
    // there the pieces have only just met, along the direction they meet in.
    if (!collideAt(dt)) return;
    const double turn = (ma.spin - mb.spin).norm() * dt;
    const int samples = std::clamp(static_cast<int>(std::ceil(turn / kSweptSampleTurn)), 2, kMaxSweptSamples);
    for (int k = 1; k < samples; ++k) {
      const std::size_t before = swept[job].size();
      const bool behind = collideAt(dt * k / samples);
      if (swept[job].size() > before || behind) break;
    }
  });
  long added = 0;
  for (std::size_t job = 0; job < firsts.size(); ++job)
    for (const Contact& c : swept[job]) {
      contacts.push_back(c);
      pairs.push_back(pairs[firsts[job]]);
      ++added;
    }
  return added;
}

}  // namespace tumble
