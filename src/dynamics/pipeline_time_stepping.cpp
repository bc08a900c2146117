// Pipeline::timeStep: one step of the time-stepping contact model (time_stepping.h). Stages, in
// order: detect within a speculative margin; project residual penetration; gravity as an impulse;
// the contact impulses; free motion of every body over dt with its new momenta (the scene's
// integrator turns the bodies, gyroscopic term included). Symplectic Euler in the momenta.
#include <algorithm>
#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_lcp.h"
#include "dynamics/pipeline.h"

namespace tumble {

void Pipeline::timeStep(World& world, const StepSettings& settings) {
  ++counters_.substeps;
  const double dt = settings.dt;
  if (has_contacts_) {
    timed(Detect, [&] { detectNow(world, settings); });
    wakeTouched(world, settings);
    timed(Correct, [&] { projectContacts(world, settings); });
  }
  // Approach speeds before gravity's impulse: the speed an impact reverses.
  std::vector<double> approach(contacts_now_.size());
  for (std::size_t i = 0; i < contacts_now_.size(); ++i) approach[i] = -normalVelocity(world, contacts_now_[i]);
  timed(Forces, [&] {
    if (!apply_gravity_) return;
    for (RigidBody& b : world.bodies)
      if (!b.is_static) b.P += b.mass * world.gravity * dt;
  });
  if (has_contacts_) {
    double min_bounce = std::max(settings.contact.resting_speed_m_s, 2 * world.gravity.norm() * dt);
    timed(Resting, [&] {
      stepper_.applyContactImpulses(world, contacts_now_, approach, settings, min_bounce, counters_.contacts);
    });
  }
  for (Wrench& w : wrenches_) w = Wrench{};
  timed(Integrate, [&] { integrate(world, wrenches_, settings); });
}

// Drift projection for the time-stepping model: the Baraff model's one push per pair (by its deepest
// point, in inverse proportion to mass, positions only) repeated in passes, each pass reading the
// depths the earlier pushes left (a contact's depth changes by the relative displacement of its two
// bodies along its normal). One pass, as the Baraff model does after every sub-step, cannot keep up
// under a load: in a column of boxes each push down into the box below is undone by the push up
// from it, and in the 1000-box pile pairs sank into each other by 6-8 cm over seconds.
void Pipeline::projectContacts(World& world, const StepSettings& settings) {
  const double tol = settings.contact.tolerance_m;
  const BodyPairGroups grouped = groupByBodyPair(contacts_now_);
  const std::vector<std::size_t>& order = grouped.order;
  moved_.assign(world.bodies.size(), Eigen::Vector3d::Zero());
  auto depthNow = [&](const Contact& c) { return c.depth - c.normal.dot(moved_[c.b] - moved_[c.a]); };
  for (int pass = 0; pass < kProjectionPasses; ++pass) {
    bool pushed = false;
    for (const auto& [begin, end] : grouped.groups) {
      std::size_t deepest = order[begin];
      for (std::size_t k = begin + 1; k < end; ++k)
        if (depthNow(contacts_now_[order[k]]) > depthNow(contacts_now_[deepest])) deepest = order[k];
      const Contact& c = contacts_now_[deepest];
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
      ++counters_.projections;
      pushed = true;
    }
    if (!pushed) break;
  }
  // The solve goes on with these contacts: their depths follow the bodies' displacements.
  for (Contact& c : contacts_now_) c.depth = depthNow(c);
}

}  // namespace tumble
