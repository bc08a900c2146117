// Colliding contacts (docs/architecture.md, collide): restitution impulses (Newton's law, or
// Poisson's or Stronge's: restitution_laws.h) that propagate through chains of contact, pair by
// pair, while the points of one body pair are always solved together.
//
// Why both. Newton's law can be imposed on all the contacts of an island at once (one LCP in the
// impulses) or on one body pair at a time, in sequence. Each is right for one of two cases that
// pull in opposite directions:
//  - a flat cube landing on four corners is ONE impact between ONE pair of bodies. Its points must
//    be solved together: the first corner solved alone would spin the cube.
//  - Newton's cradle is a CHAIN of impacts between DIFFERENT pairs. In the real cradle the shock
//    passes from ball to ball, one impact after another (with gaps of 1e-6 m back-stepping finds
//    them as four separate events). Solving all pairs at once gives [-0.6, 0.4, 0.4, 0.4, 0.4] m/s:
//    momentum and energy conserved, and wrong; one pair after another gives [0, 0, 0, 0, 1].
// So the unit of simultaneity is the body pair: its manifold is one impact. Across pairs, the pair
// approaching fastest is solved first; its impulse changes the velocities its neighbours see, and
// the next pair that now approaches is solved next, until no contact of the island approaches
// (Guendelman, Bridson and Fedkiw 2003 iterate over pairs in the same spirit).
// An island where no point bounces (every restitution 0, or every approach slower than the least
// bounce) has no wave to follow: it is a plastic impact, solved simultaneously over the island
// (J.-J. Moreau, "Unilateral contact and dry friction in finite freedom dynamics", 1988). Pair by
// pair it would be Gauss-Seidel stopped short, and with friction its answer depends on the order:
// a tent of two cards landing on a loose card took its feet's impulses first and spun its cards.
//
// Termination: the first rounds use each contact's restitution; after a few rounds per pair
// (bodies pinched between others can trade an elastic impulse back and forth for ever) the rounds
// are inelastic, which dissipates, and if even that has not settled the island after a cap, one
// simultaneous inelastic solve over the whole island leaves no contact approaching.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

// When an impact's lift-offs settle (resolveImpact below): a lift-off that gravity ends within
// `within_s` is not kept, and a lift-off slower than `slack_m_s` is none. 4 dt is the flight of
// the slowest bounce the step resolves (minBounceSpeed, contact_solve_common.h: up at 2 g dt, back
// after 4 dt); a swing shorter than that is below what the step can follow. The slack is a tenth
// of the resting speed: slower than that, a point is at rest for every stage.
struct SettleRule {
  double within_s = 0;
  double slack_m_s = 0;
};
inline SettleRule settleRule(const ContactSettings& s, double dt) { return {4 * dt, 0.1 * s.resting_speed_m_s}; }

// Resolves one island of touching contacts (bodies that touch, directly or through others) so that
// afterwards no contact approaches faster than settings.resting_speed_m_s. Impacts slower than
// `min_bounce_speed` (along each normal) get no restitution (see Pipeline); lift-offs too short for a step of
// `dt` to follow settle (settleRule).
// `outside`: the contacts not in any island (touching and separating, or within the margin), which
// an elastic pair impact may have to take in (neighbour_turn_back.h).
void propagateImpulses(World& world, const std::vector<const Contact*>& island,
                       const std::vector<const Contact*>& outside, const ContactSettings& settings, const BounceThreshold& min_bounce_speed, double dt,
                       ContactSolveStats& stats);

// All the island's contacts at once, inelastic: nothing approaching after, no energy added.
void plasticImpact(World& world, const std::vector<const Contact*>& island, const ContactSettings& s,
                   const BounceThreshold& min_bounce_speed, const SettleRule& settle, ContactSolveStats& stats);
// The same with the settle rule of a step of `dt`.
void plasticIslandImpact(World& world, const std::vector<const Contact*>& island, const ContactSettings& s,
                         const BounceThreshold& min_bounce_speed, double dt, ContactSolveStats& stats);

// One simultaneous impact on `points`: Newton's law v+ >= -e v-, j >= 0, (v+ + e v-) j = 0 on every
// normal, Coulomb on impulses (|j_t| <= mu j_n, aiming at zero tangential velocity), as one LCP in
// the impulses; or with `law` Poisson's or Stronge's (restitution_laws.h). e is scaled by
// `restitution_scale` in [0, 1]. Never adds kinetic energy (impact_energy.h: Newton's law with
// friction can, Kane's paradox).
// With a settle rule, an impact whose lift-offs gravity would end within the rule's time then
// settles: no touching point leaves faster than it did before (see the .cpp).
void resolveImpact(World& world, const std::vector<const Contact*>& points, const BounceThreshold& min_bounce_speed,
                   double restitution_scale, RestitutionLaw law, ContactSolveStats& stats,
                   const SettleRule* settle = nullptr);

}  // namespace tumble
