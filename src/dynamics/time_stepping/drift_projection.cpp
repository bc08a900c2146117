#include "dynamics/time_stepping/drift_projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/settings.h"

namespace tumble {

long DriftProjection::project(World& world, std::vector<Contact>& contacts, double tol, bool deep_only) {
  groupByBodyPair(contacts, grouped_);
  const BodyPairGroups& grouped = grouped_;
  const std::vector<std::size_t>& order = grouped.order;
  const std::size_t bodies = world.bodies.size();
  start_.resize(bodies);
  inverse_inertia_.resize(bodies);
  moved_.assign(bodies, Eigen::Vector3d::Zero());
  turned_.assign(bodies, Eigen::Vector3d::Zero());
  // Only the bodies a contact names are read below: the rest keep stale entries. Each once,
  // though a body in a pile is named by a dozen contacts.
  named_.assign(bodies, 0);
  for (const Contact& c : contacts)
    for (int k : {c.a, c.b}) {
      if (named_[k]) continue;
      named_[k] = 1;
      start_[k] = world.bodies[k].x;
      inverse_inertia_[k] = inverseInertiaWorld(world.bodies[k]);   // zero when static
    }
  // A material point at world p (at the start) has moved by Delta x + Delta theta x (p - x).
  auto shift = [&](int k, const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return moved_[k] + turned_[k].cross(p - start_[k]);
  };
  auto depthNow = [&](const Contact& c) { return c.depth - c.normal.dot(shift(c.b, c.point) - shift(c.a, c.point)); };
  // A contact's Response (the header) is fixed for the whole projection (start poses, start
  // inertia), so it is worked out once per contact, at the first visit of its pair.
  // Under gravity, a deep pass treats the lower body of a pair stacked along gravity as fixed
  // (shock propagation, below and in the header): `shock` selects that response.
  const double g = world.gravity.norm();
  const Eigen::Vector3d up = g > 0 ? Eigen::Vector3d(-world.gravity / g) : Eigen::Vector3d::Zero();
  auto responseOf = [&](const Contact& c, bool shock) {
    Response r;
    // The lower body is held only if the upper one can move (not under a fixed or sleeping body).
    const double rise = c.normal.dot(up);   // > 0: B above A
    const bool hold_a = shock && rise >= tuning::kProjectionStackedCos && world.bodies[c.b].inv_mass > 0;
    const bool hold_b = shock && -rise >= tuning::kProjectionStackedCos && world.bodies[c.a].inv_mass > 0;
    const double mass_a = hold_a ? 0 : world.bodies[c.a].inv_mass, mass_b = hold_b ? 0 : world.bodies[c.b].inv_mass;
    const Eigen::Vector3d ta = (c.point - start_[c.a]).cross(c.normal), tb = (c.point - start_[c.b]).cross(c.normal);
    r.turn_a = hold_a ? Eigen::Vector3d::Zero() : Eigen::Vector3d(inverse_inertia_[c.a] * ta);
    r.turn_b = hold_b ? Eigen::Vector3d::Zero() : Eigen::Vector3d(inverse_inertia_[c.b] * tb);
    r.mass_a = mass_a;
    r.mass_b = mass_b;
    r.translating = mass_a + mass_b;
    r.turning = r.translating + ta.dot(r.turn_a) + tb.dot(r.turn_b);
    r.largest_turn = std::max(r.turn_a.norm(), r.turn_b.norm());
    return r;
  };
  auto push = [&](const Contact& c, const Response& r, double lambda, bool turning) {
    moved_[c.a] -= r.mass_a * lambda * c.normal;
    moved_[c.b] += r.mass_b * lambda * c.normal;
    if (!turning) return;
    turned_[c.a] -= r.turn_a * lambda;
    turned_[c.b] += r.turn_b * lambda;
  };
  pushed_.assign(contacts.size(), 0);
  responses_.resize(2 * contacts.size());
  has_response_.assign(2 * contacts.size(), 0);
  // A pair's depths change only when one of its bodies is pushed, so a pair found shallow is not
  // looked at again until one of them has been: pushes are numbered, and each body keeps the number
  // of its last, each pair the number current when it was found shallow.
  long pushed_so_far = 0;
  last_push_.assign(bodies, -1);
  found_shallow_.assign(grouped.groups.size(), std::numeric_limits<long>::min());
  long pushes = 0;
  for (int pass = 0; pass < tuning::kProjectionMaxPasses; ++pass) {
    // Past the first passes (from the first, for a speed setting), only pairs with a point far
    // deeper than the tolerance are pushed (a landing), until none is left: a pass that moves
    // nothing ends the projection.
    const bool shallow_too = pass < tuning::kProjectionPasses && !deep_only;
    const double deep_from = shallow_too ? tol : tuning::kProjectionDeepFactor * tol;
    const std::size_t which = shallow_too ? 0 : contacts.size();   // responses: own, or shock's
    bool moved_any = false;
    for (std::size_t g = 0; g < grouped.groups.size(); ++g) {
      const auto [begin, end] = grouped.groups[g];
      const Contact& named = contacts[order[begin]];
      if (std::max(last_push_[named.a], last_push_[named.b]) <= found_shallow_[g]) continue;
      bool deep = false;
      for (std::size_t k = begin; k < end && !deep; ++k) deep = depthNow(contacts[order[k]]) > deep_from;
      if (!deep) {
        found_shallow_[g] = pushed_so_far;
        continue;
      }
      // The pair's points in turn: each pushed back to half the tolerance, a push that proves too
      // much taken back only as far as the pair has pushed at that point in this pass.
      for (std::size_t k = begin; k < end; ++k) {
        const std::size_t i = order[k];
        pushed_[i] = 0;
        if (!has_response_[which + i]) responses_[which + i] = responseOf(contacts[i], !shallow_too), has_response_[which + i] = 1;
      }
      for (int sweep = 0; sweep < tuning::kProjectionPairSweeps; ++sweep) {
        double largest = 0;
        for (std::size_t k = begin; k < end; ++k) {
          const Contact& c = contacts[order[k]];
          const Response& r = responses_[which + order[k]];
          double stiff = r.turning;
          if (!(stiff > 0)) continue;
          double& total = pushed_[order[k]];
          const double excess = depthNow(c) - 0.5 * tol;
          // Not deeper than half the tolerance and not pushed yet in this pass: nothing to do (the
          // push below would be zero), and no division to wait for.
          if (total == 0 && !(excess > 0)) continue;
          double lambda = std::max(-total, excess / stiff);
          if (lambda == 0 || (total == 0 && lambda < 0)) continue;
          // Drift turns a body by far less than kProjectionMaxTurn; a push that would turn it
          // more is an overlap a violent step left, and is made by translation (see the header).
          const bool turning = r.largest_turn * std::abs(lambda) <= tuning::kProjectionMaxTurn;
          if (!turning) {
            stiff = r.translating;
            lambda = std::max(-total, (depthNow(c) - 0.5 * tol) / stiff);
          }
          push(c, r, lambda, turning);
          ++pushed_so_far;
          for (int body : {c.a, c.b})
            if (!world.bodies[body].is_static) last_push_[body] = pushed_so_far;
          total += lambda;
          largest = std::max(largest, std::abs(lambda) * stiff);
        }
        if (largest <= 0.5 * tol) break;
      }
      ++pushes;
      moved_any = true;
    }
    if (!moved_any) break;
  }
  for (Contact& c : contacts) c.depth = depthNow(c);
  for (const Contact& c : contacts)
    for (int k : {c.a, c.b}) {
      RigidBody& body = world.bodies[k];
      if (body.is_static) continue;
      body.x = start_[k] + moved_[k];
      const double angle = turned_[k].norm();
      if (angle > 0) body.q = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, turned_[k] / angle)) * body.q).normalized();
      turned_[k].setZero();   // a body named by several contacts turns once
      moved_[k].setZero();
      start_[k] = body.x;
    }
  return pushes;
}

}  // namespace tumble
