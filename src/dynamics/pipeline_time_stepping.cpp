// Pipeline::timeStep: one step of the time-stepping contact model (time_stepping.h). Stages, in
// order: detect within a speculative margin; project residual penetration; gravity as an impulse;
// the contact impulses; free motion of every body over dt with its new momenta (the scene's
// integrator turns the bodies, gyroscopic term included). Symplectic Euler in the momenta.
#include <cmath>

#include "dynamics/contact_lcp.h"
#include "dynamics/pipeline.h"

namespace tumble {

void Pipeline::timeStep(World& world, const StepSettings& settings) {
  ++counters_.substeps;
  const double dt = settings.dt;
  if (has_contacts_) {
    timed(Detect, [&] {
      bodyReach(world, body_radius_, dt, reach_);
      detector_.detect(world, settings.contact, contacts_now_, &pairs_now_, &reach_);
    });
    timed(Correct, [&] { correctPenetration(world, settings); });
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

}  // namespace tumble
