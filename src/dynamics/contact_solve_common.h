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
  long friction_fallbacks = 0;      // islands whose dynamic friction diverged (boxed friction used)
  long iterative_islands = 0;       // resting islands solved by Gauss-Seidel (too large to pivot)
  long iterative_fallbacks = 0;     // of those: pivoting stopped short with unusable forces
  long sweeps = 0, unconverged_sweeps = 0;   // Gauss-Seidel sweeps; solves that hit the cap
  long active_set_steps = 0;        // subspace steps on islands Gauss-Seidel left unconverged
};

// An impact in which no point approaches faster than this settles: no touching point may leave
// faster than it did before (baraff/impulse_propagation.cpp, settleSlowImpact), and back-stepping
// does not time landings this slow (baraff/back_step.cpp): they settle whenever they are found.
// 0.08 m/s: a lift-off that slow rises 0.3 mm and is back within 16 ms; it is the speed below
// which bounces are made inelastic at the default step (2 g dt, dt = 1/240 s), but fixed, not
// scaled with dt: scaled, it made the domino wave 15 % faster at dt than at dt/2.
inline double settleSpeed(const ContactSettings& s) { return 80 * s.resting_speed_m_s; }

// A bounce slower than what gravity takes away in about two steps cannot leave the surface for a
// whole step: resolved elastically it would come back every step (v -> e v - g dt has the fixed
// point g dt / (1 - e)) and never come to rest. Impacts slower than this are made inelastic.
inline double minBounceSpeed(const World& world, const ContactSettings& s, double dt) {
  return std::max(s.resting_speed_m_s, 2 * world.gravity.norm() * dt);
}

}  // namespace tumble
