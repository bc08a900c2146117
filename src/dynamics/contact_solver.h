// Contact pipeline steps 4-6 (DESIGN.md): classify contacts by their normal relative velocity,
// resolve colliding ones with impulses (Newton's restitution law, propagated pair by pair with
// each pair's points solved together: impulse_propagation.h), and find the forces of resting ones (Baraff's LCP a = A f + b, a >= 0, f >= 0,
// a^T f = 0) with Coulomb friction.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

enum class ContactClass { Separating, Resting, Colliding };

// Touching contacts (|depth| within tolerance) only; others are Separating.
ContactClass classify(const World& world, const Contact& c, const ContactSettings& settings);

struct ContactSolveStats {
  long colliding = 0, resting = 0;  // contacts of each class seen
  long pivots = 0;                  // LCP pivots spent
  long failures = 0;                // LCP solves that did not converge (result used anyway)
  long friction_fallbacks = 0;      // islands whose dynamic friction diverged (boxed friction used)
  long iterative_islands = 0;       // resting islands solved by Gauss-Seidel (too large to pivot)
  long iterative_fallbacks = 0;     // of those: pivoting stopped short with unusable forces
  long sweeps = 0, unconverged_sweeps = 0;   // Gauss-Seidel sweeps; solves that hit the cap
};

// An impact in which no point approaches faster than this settles: no touching point may leave
// faster than it did before (impulse_propagation.cpp, settleSlowImpact), and back-stepping does
// not time landings this slow (pipeline.cpp): they settle whenever they are found. 0.08 m/s: a
// lift-off that slow rises 0.3 mm and is back within 16 ms; it is the speed below which bounces
// are made inelastic at the default step (2 g dt, dt = 1/240 s), but fixed, not scaled with dt:
// scaled, it made the domino wave 15 % faster at dt than at dt/2.
inline double settleSpeed(const ContactSettings& s) { return 80 * s.resting_speed_m_s; }

// Applies restitution impulses to every colliding contact and passes them on through the touching
// contacts around them (a flat face landing on 4 corners is one impact, solved at once; a chain of
// balls passes it on ball by ball). Returns true if any contact was colliding.
// Impacts slower than `min_bounce_speed` (m/s) get no restitution: see Pipeline for why.
bool resolveCollisions(World& world, const std::vector<Contact>& contacts,
                       const ContactSettings& settings, double min_bounce_speed,
                       ContactSolveStats& stats);

// The resting-force solve's memory between calls: each contact's impulse over step_s (every
// island's, pivoted ones too), so that an island too large to pivot starts Gauss-Seidel warm.
struct RestingMemory {
  ImpulseMemory last;                 // impulses over step_s (N s on B, world axes) of the last call
  std::vector<ImpulseRecord> next;    // this call's, gathered while solving
};

// Adds the resting-contact forces (normal and friction) to `wrenches`, which hold the applied
// forces on entry (they determine the accelerations the contacts must cancel). Islands of more
// than settings.max_direct_rows rows are solved iteratively: with a `memory` (and step_s > 0) at
// the velocity level over step_s, warm-started from the last call (contact_solver.cpp,
// restIslandAtVelocityLevel); without one on the accelerations, from zero, where a sliding
// contact's friction stops at what would halt the slide within step_s (0: exactly mu f_n).
void addRestingForces(const World& world, const std::vector<Contact>& contacts,
                      const ContactSettings& settings, std::vector<Wrench>& wrenches,
                      ContactSolveStats& stats, double step_s = 0, RestingMemory* memory = nullptr);

}  // namespace tumble
