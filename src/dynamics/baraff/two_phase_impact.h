// Poisson's and Stronge's laws over the several points of one impact (a face landing on its four
// corners), where the laws, defined for one point, need a rule for how the points share the
// impulse. The choice here: two LCPs in the impulses, each with Coulomb friction (contact_rows.h),
// one per phase of the impact.
//  - Compression: the inelastic impact (e = 0): every point ends with v_n >= 0, and its normal
//    impulse p_c,i is the impulse that ends its compression.
//  - Restitution, from the velocities compression left: every point's normal impulse is at least
//    s e_i p_c,i (a lower bound in the LCP, so a point that others' restitution drives into the
//    surface takes more), v_n >= 0 after, and Coulomb friction bounded by the phase's own normal
//    impulse. Poisson: s = 1, restitution gives e_i times each point's compression impulse. Stronge:
//    s such that the work the normal impulses do in restitution is e_i^2 times what they absorbed
//    in compression, summed over the points; an impulse changes the velocities linearly, so a
//    phase's normal work at a point is p_i (v_i before + v_i after) / 2.
// Why: it is the one-point law at each point whenever the points do not disturb each other, and
// without friction both laws give Newton's answer (the compression LCP leaves v_n = 0 where
// p_c > 0, and e p_c then gives v_n = -e v-; the normal work is then e^2 of compression's). With
// friction it keeps what the laws are about: restitution scales the compression impulse (Poisson)
// or its energy (Stronge), not the velocities. Each phase alone adds no energy when e = 0 (the
// inelastic LCP: impulse_propagation.cpp), and restitution_laws.cpp keeps the energy rule.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

// Applies the two phases to `points` with restitution e[i] at point i under `law` (Poisson or
// Stronge); `friction` false leaves out the friction rows (each phase is then a projection).
void applyTwoPhaseImpact(World& world, const std::vector<const Contact*>& points, const std::vector<double>& e,
                         RestitutionLaw law, bool friction, ContactSolveStats& stats);

}  // namespace tumble
