#include "dynamics/time_stepping/drift_projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/settings.h"

namespace tumble {

long DriftProjection::project(World& world, std::vector<Contact>& contacts, double tol) {
  groupByBodyPair(contacts, grouped_);
  const BodyPairGroups& grouped = grouped_;
  const std::vector<std::size_t>& order = grouped.order;
  const std::size_t bodies = world.bodies.size();
  start_.resize(bodies);
  inverse_inertia_.resize(bodies);
  moved_.assign(bodies, Eigen::Vector3d::Zero());
  turned_.assign(bodies, Eigen::Vector3d::Zero());
  // Only the bodies a contact names are read below: the rest keep stale entries.
  for (const Contact& c : contacts)
    for (int k : {c.a, c.b}) {
      start_[k] = world.bodies[k].x;
      inverse_inertia_[k] = inverseInertiaWorld(world.bodies[k]);   // zero when static
    }
  // A material point at world p (at the start) has moved by Delta x + Delta theta x (p - x).
  auto shift = [&](int k, const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return moved_[k] + turned_[k].cross(p - start_[k]);
  };
  auto depthNow = [&](const Contact& c) { return c.depth - c.normal.dot(shift(c.b, c.point) - shift(c.a, c.point)); };
  // The push that moves c's two points apart by `depth` along its normal, with the least
  // mass-weighted motion: lambda = depth / K, K = w_a + w_b + (r_a x n) I_a^-1 (r_a x n) + (r_b x n) I_b^-1 (r_b x n);
  // a unit push turns A by -I_a^-1 (r_a x n) and B by I_b^-1 (r_b x n). Without turning, the push
  // translates the two bodies only (K = w_a + w_b).
  struct Response {
    double translating = 0, turning = 0;   // K
    Eigen::Vector3d turn_a, turn_b;        // the turns of a unit push
  };
  auto responseOf = [&](const Contact& c) {
    Response r;
    const Eigen::Vector3d ta = (c.point - start_[c.a]).cross(c.normal), tb = (c.point - start_[c.b]).cross(c.normal);
    r.turn_a = inverse_inertia_[c.a] * ta;
    r.turn_b = inverse_inertia_[c.b] * tb;
    r.translating = world.bodies[c.a].inv_mass + world.bodies[c.b].inv_mass;
    r.turning = r.translating + ta.dot(r.turn_a) + tb.dot(r.turn_b);
    return r;
  };
  auto push = [&](const Contact& c, const Response& r, double lambda, bool turning) {
    moved_[c.a] -= world.bodies[c.a].inv_mass * lambda * c.normal;
    moved_[c.b] += world.bodies[c.b].inv_mass * lambda * c.normal;
    if (!turning) return;
    turned_[c.a] -= r.turn_a * lambda;
    turned_[c.b] += r.turn_b * lambda;
  };
  pushed_.assign(contacts.size(), 0);
  long pushes = 0;
  for (int pass = 0; pass < tuning::kProjectionPasses; ++pass) {
    bool moved_any = false;
    for (const auto& [begin, end] : grouped.groups) {
      bool deep = false;
      for (std::size_t k = begin; k < end && !deep; ++k) deep = depthNow(contacts[order[k]]) > tol;
      if (!deep) continue;
      // The pair's points in turn: each pushed back to half the tolerance, a push that proves too
      // much taken back only as far as the pair has pushed at that point in this pass.
      for (std::size_t k = begin; k < end; ++k) pushed_[order[k]] = 0;
      for (int sweep = 0; sweep < tuning::kProjectionPairSweeps; ++sweep) {
        double largest = 0;
        for (std::size_t k = begin; k < end; ++k) {
          const Contact& c = contacts[order[k]];
          const Response r = responseOf(c);
          double stiff = r.turning;
          if (!(stiff > 0)) continue;
          double& total = pushed_[order[k]];
          double lambda = std::max(-total, (depthNow(c) - 0.5 * tol) / stiff);
          if (lambda == 0 || (total == 0 && lambda < 0)) continue;
          // Drift turns a body by far less than kProjectionMaxTurn; a push that would turn it
          // more is an overlap a violent step left, and is made by translation (see the header).
          const bool turning = std::max(r.turn_a.norm(), r.turn_b.norm()) * std::abs(lambda) <= tuning::kProjectionMaxTurn;
          if (!turning) {
            stiff = r.translating;
            lambda = std::max(-total, (depthNow(c) - 0.5 * tol) / stiff);
          }
          push(c, r, lambda, turning);
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
