#include "dynamics/passive_impulses.h"

#include <algorithm>
#include <cmath>

namespace tumble {

ImpulseMerit impulseMerit(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                          const std::vector<RowLimit>& limits, Eigen::Ref<const Eigen::VectorXd> p, double gravity_dt) {
  // Each moving body's summed impulse and moment, in buffers kept per thread: `local_of` is the
  // size of the world but reset only where this call wrote it.
  thread_local std::vector<int> local_of;
  thread_local std::vector<int> bodies;
  thread_local std::vector<Eigen::Vector3d> linear, angular;
  local_of.resize(world.bodies.size(), -1);
  bodies.clear();
  linear.clear();
  angular.clear();
  ImpulseMerit m;
  const bool with_work = gravity_dt > 0;
  auto add = [&](int body, const Eigen::Vector3d& impulse, const Eigen::Vector3d& moment) {
    if (world.bodies[body].is_static) return;
    if (local_of[body] < 0) {
      local_of[body] = static_cast<int>(bodies.size());
      bodies.push_back(body);
      linear.push_back(Eigen::Vector3d::Zero());
      angular.push_back(Eigen::Vector3d::Zero());
    }
    linear[local_of[body]] += impulse;
    angular[local_of[body]] += moment;
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (p[i] == 0) continue;
    const ContactRow& r = rows[i];
    const double aim = limits[i].kind == RowLimit::Sliding ? b[i] - limits[i].target : b[i];
    m.linear += aim * p[i];
    const Eigen::Vector3d impulse = p[i] * r.dir;
    add(r.b, impulse, r.rb.cross(impulse));
    add(r.a, -impulse, -r.ra.cross(impulse));
  }
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const RigidBody& body = world.bodies[bodies[k]];
    m.quadratic += body.inv_mass * linear[k].squaredNorm() + angular[k].dot(inverseInertiaWorld(body) * angular[k]);
    if (with_work) {
      m.work += linear[k].dot(body.velocity()) + angular[k].dot(body.angularVelocity());
      m.lift -= gravity_dt * world.gravity.dot(linear[k]);
      m.fall += 0.5 * body.mass * world.gravity.squaredNorm() * gravity_dt * gravity_dt;
    }
    local_of[bodies[k]] = -1;
  }
  return m;
}

double keepPassive(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                   const std::vector<RowLimit>& limits, Eigen::Ref<Eigen::VectorXd> p, double gravity_dt) {
  const ImpulseMerit m = impulseMerit(world, rows, b, limits, p, gravity_dt);
  double alpha = 1;
  if (m.value() > 0) {
    // merit(alpha p) = alpha linear + alpha^2 quadratic / 2, lowest at -linear / quadratic; with
    // merit(p) > 0 that lies below 1, and at 0 where the impulses only push along the motion.
    alpha = m.quadratic > 0 ? std::clamp(-m.linear / m.quadratic, 0.0, 1.0) : 0.0;
  }
  if (gravity_dt > 0) {
    // The step's total energy against its start (the header): alpha (work + lift) + alpha^2
    // quadratic / 2 may not exceed `fall`, up to rounding of the terms.
    const double slope = m.work + m.lift;
    auto rise = [&](double a) { return a * slope + 0.5 * a * a * m.quadratic - m.fall; };
    const double slack = kEnergySlack * (std::abs(m.work) + std::abs(m.lift) + m.quadratic + m.fall);
    if (rise(alpha) > slack) {
      // The positive root of rise(a) = 0 (rise(0) = -fall <= 0, and rise is convex).
      const double root = m.quadratic > 0
                              ? (-slope + std::sqrt(slope * slope + 2 * m.quadratic * m.fall)) / m.quadratic
                              : (slope > 0 ? m.fall / slope : alpha);
      alpha = std::clamp(root, 0.0, alpha);
    }
  }
  if (alpha < 1) p *= alpha;
  return alpha;
}

}  // namespace tumble
