#include "dynamics/time_stepping/drift_projection.h"

#include "dynamics/contact_islands.h"
#include "dynamics/settings.h"

namespace tumble {

long DriftProjection::project(World& world, std::vector<Contact>& contacts, double tol) {
  groupByBodyPair(contacts, grouped_);
  const BodyPairGroups& grouped = grouped_;
  const std::vector<std::size_t>& order = grouped.order;
  moved_.assign(world.bodies.size(), Eigen::Vector3d::Zero());
  auto depthNow = [&](const Contact& c) { return c.depth - c.normal.dot(moved_[c.b] - moved_[c.a]); };
  long pushes = 0;
  for (int pass = 0; pass < tuning::kProjectionPasses; ++pass) {
    bool pushed = false;
    for (const auto& [begin, end] : grouped.groups) {
      std::size_t deepest = order[begin];
      for (std::size_t k = begin + 1; k < end; ++k)
        if (depthNow(contacts[order[k]]) > depthNow(contacts[deepest])) deepest = order[k];
      const Contact& c = contacts[deepest];
      const double depth = depthNow(c);
      if (depth <= tol) continue;
      RigidBody& A = world.bodies[c.a];
      RigidBody& B = world.bodies[c.b];
      const double wa = A.inv_mass, wb = B.inv_mass;
      if (wa + wb <= 0) continue;
      const double push = depth - 0.5 * tol;
      const Eigen::Vector3d da = -c.normal * (push * wa / (wa + wb)), db = c.normal * (push * wb / (wa + wb));
      A.x += da;
      B.x += db;
      moved_[c.a] += da;
      moved_[c.b] += db;
      ++pushes;
      pushed = true;
    }
    if (!pushed) break;
  }
  for (Contact& c : contacts) c.depth = depthNow(c);
  return pushes;
}

}  // namespace tumble
