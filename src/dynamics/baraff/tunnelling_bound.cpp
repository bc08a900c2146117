#include "dynamics/baraff/tunnelling_bound.h"

#include <algorithm>
#include <cmath>

namespace tumble {

// Per pair of pieces that can meet within the sub-step: they are now at least `gap` apart along an
// axis n, and the gap along a fixed axis closes no faster than
//   c = n . (v_a - v_b) + |w_a| r_a + |w_b| r_b + (|a_a| + |a_b|) h
// so within (gap + t/2) / c seconds they cannot overlap by more than half the thinner piece's
// width t along n, hence by no more than that at all, and cannot pass through each other without
// ending the sub-step overlapping, which back-stepping then resolves. A shot far from everything
// is not cut; one approaching a thin wall is cut once, at the wall; one sliding along a wall at
// speed is not cut by its speed along the wall.
double TunnellingBound::limit(const World& world, const std::vector<Wrench>& wrenches,
                              const std::vector<double>& body_radius, double min_thickness,
                              ContactDetector& detector, double h) {
  double fastest = 0;
  speed_.assign(world.bodies.size(), 0.0);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static) continue;
    // |v| + |a| h + |w| r bounds the body's point speeds over the sub-step
    speed_[i] = b.velocity().norm() + wrenches[i].force.norm() * b.inv_mass * h +
                b.angularVelocity().norm() * body_radius[i];
    fastest = std::max(fastest, speed_[i]);
  }
  // Nothing can cross even the thinnest piece: no pair needs looking at.
  if (fastest <= 0 || !std::isfinite(min_thickness) || min_thickness >= 4 * fastest * h) return h;
  reach_.resize(world.bodies.size());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) reach_[i] = speed_[i] * h;
  detector.nearPairs(world, reach_, near_);
  auto approach = [&](int body, const Eigen::Vector3d& n) {
    const RigidBody& b = world.bodies[body];
    if (b.is_static) return 0.0;
    return n.dot(b.velocity()) + wrenches[body].force.norm() * b.inv_mass * h +
           b.angularVelocity().norm() * body_radius[body];
  };
  double bound = h;
  for (const ContactDetector::NearPair& p : near_) {
    const bool has_axis = p.axis.squaredNorm() > 0.5;
    const double closing = has_axis ? approach(p.body_a, p.axis) + approach(p.body_b, -p.axis)
                                    : speed_[p.body_a] + speed_[p.body_b];
    if (closing > 0) bound = std::min(bound, (p.gap + 0.5 * p.thickness) / closing);
  }
  return std::max(bound, 1e-9 * h);
}

}  // namespace tumble
