// Contact pipeline step 6 of the Baraff model: the forces of resting contacts (Baraff's LCP
// a = A f + b, a >= 0, f >= 0, a^T f = 0; Baraff 1994) with Coulomb friction, added to the applied
// forces before the sub-step is integrated.
//
// Each island of resting contacts gets one of four solves. The choice is explicit (chooseRestingSolve)
// and the fallbacks are named where they happen:
//   Pivoting            the default, exact: Dantzig pivoting with static friction in the LCP and
//                       dynamic friction (mu f_n against the slide) found by fixed-point iteration
//   BoxedFriction       when that iteration diverges (a wedged sliding body): every contact gets
//                       boxed friction |f_t| <= mu f_n, as ODE and Bullet treat all contacts
//   AccelerationSweeps  when pivoting stops short with unusable forces, or an island too large to
//                       pivot has no memory to start from: Gauss-Seidel on the accelerations, from 0
//   VelocityLevel       an island too large to pivot, with a memory: the impulses over the step,
//                       warm-started from the last call (island_impulses.h), as time stepping does
// In a world with joints every one of the four takes the joints' rows into its problem
// (joints/contact_joint_lcp.h), so that a jointed body's contact forces are those its joints
// allow: a body hanging from a hinge with its end on the ground, solved as if it were free, gets
// a push the hinge then turns into a creep along the ground.
#pragma once

#include <optional>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

enum class RestingSolve { Pivoting, BoxedFriction, AccelerationSweeps, VelocityLevel };

// The resting-force solve's memory between calls: each contact's impulse over the step (every
// island's, pivoted ones too), so that an island too large to pivot starts Gauss-Seidel warm.
struct RestingMemory {
  ImpulseMemory last;                 // impulses over step_s (N s on B, world axes) of the last call
  std::vector<ImpulseRecord> next;    // this call's, gathered while solving
};

// Everything one resting-force solve reads and writes.
struct RestingContext {
  const World& world;
  const ContactSettings& settings;
  // s: the (sub-)step the forces will act over. Static friction then stops a residual slip within
  // it, and a slide that friction would stop within it is held by static friction. 0: the forces
  // of this instant only (no velocity-level solve).
  double step_s;
  RestingMemory* memory;              // null: no warm start, and nothing remembered
  std::vector<Wrench>& wrenches;      // in: the applied forces; out: plus the contact forces
  ContactSolveStats& stats;
  // Every island starts with this solve instead of chooseRestingSolve's (VelocityLevel only where
  // there is a memory and a step): for tests that must reach a fallback on a scene that would not
  // need it. None in a run.
  std::optional<RestingSolve> forced = std::nullopt;
};

// Pivoting unless the island is too large to pivot (contact_rows.h): then VelocityLevel when there
// is a memory and a step, AccelerationSweeps otherwise.
RestingSolve chooseRestingSolve(const std::vector<const Contact*>& island, const RestingContext& ctx);

// Adds the resting-contact forces (normal and friction) of every island of resting contacts.
void addRestingForces(const std::vector<Contact>& contacts, const RestingContext& ctx);

}  // namespace tumble
