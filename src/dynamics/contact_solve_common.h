// What every contact model's solve shares: its counters, and the speeds below which an impact is
// not a bounce. Each model includes this header, never another model's.
#pragma once

#include <algorithm>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

struct ContactSolveStats {
  long colliding = 0, resting = 0;  // contacts of each class seen
  long pivots = 0;                  // LCP pivots spent
  long failures = 0;                // LCP solves that did not converge (result used anyway)
  long lemke_settled = 0;           // solves whose friction passes did not settle, by complementary pivoting
  long friction_fallbacks = 0;      // islands whose dynamic friction diverged (boxed friction used)
  long iterative_islands = 0;       // resting islands solved by Gauss-Seidel (too large to pivot)
  long iterative_fallbacks = 0;     // of those: pivoting stopped short with unusable forces
  long sweeps = 0, unconverged_sweeps = 0;   // Gauss-Seidel sweeps; solves that hit the cap
  long active_set_steps = 0;        // subspace steps on islands Gauss-Seidel left unconverged
  long passive_scaled = 0;          // unconverged answers scaled down so as not to add energy
  long merged_impacts = 0;          // pair impacts grown by neighbours that turned their lift-off back

  ContactSolveStats& operator+=(const ContactSolveStats& o) {
    colliding += o.colliding, resting += o.resting, pivots += o.pivots, failures += o.failures;
    lemke_settled += o.lemke_settled;
    friction_fallbacks += o.friction_fallbacks, iterative_islands += o.iterative_islands;
    iterative_fallbacks += o.iterative_fallbacks, sweeps += o.sweeps, unconverged_sweeps += o.unconverged_sweeps;
    active_set_steps += o.active_set_steps, passive_scaled += o.passive_scaled;
    merged_impacts += o.merged_impacts;
    return *this;
  }
};

// The slowest impact that bounces, contact by contact. A bounce slower than what gravity takes away
// along the contact's normal in about two steps cannot leave the surface for a whole step: resolved
// elastically it would come back every step (v -> e v - g.n dt has the fixed point g.n dt / (1 - e))
// and never come to rest, so impacts slower than that are made inelastic. Gravity takes nothing
// from a bounce off a wall: there only the resting speed bounds it. (One bound for every normal,
// 2 |g| dt = 8.2 cm/s at dt = 1/240 s, stopped anything rolling or sliding into a wall slower than
// that dead whatever its restitution, and so every impact in a bin of beads a few millimetres
// across.)
struct BounceThreshold {
  double resting_m_s = 0;                             // ContactSettings::resting_speed_m_s
  Eigen::Vector3d gravity_dt2 = Eigen::Vector3d::Zero();   // 2 g dt
  double along(const Eigen::Vector3d& normal) const {
    return std::max(resting_m_s, std::abs(gravity_dt2.dot(normal)));
  }
};

inline BounceThreshold minBounceSpeed(const World& world, const ContactSettings& s, double dt) {
  return {s.resting_speed_m_s, 2 * dt * world.gravity};
}

}  // namespace tumble
