// Poisson's (kinetic) and Stronge's (energetic) coefficients of restitution for Baraff impacts,
// beside Newton's (kinematic) in impulse_propagation.cpp; scenes choose with
// "restitution_law" (settings.h, RestitutionLaw). With v_n the normal relative velocity, p_n the
// normal impulse, p_c its value when compression ends (v_n = 0) and p_f at the end, and
// W(p) = integral of v_n dp_n the normal impulse's work:
//   Newton   e = -v_n+ / v_n-
//   Poisson  e = (p_f - p_c) / p_c
//   Stronge  e^2 = -(W(p_f) - W(p_c)) / W(p_c)
// (W. J. Stronge, "Impact Mechanics", 2000; "Rigid body collisions with friction", Proc. R. Soc.
// Lond. A, 1990). Without friction, or while the slip keeps its direction, the three agree; where
// friction stops or reverses the slip during the impact (a slender rod striking a rough floor at
// an angle) they differ, and only Stronge's never adds energy by itself.
// One point: the impact followed in impulse space (point_impact.h). Several points of one impact:
// two LCPs, compression then restitution (two_phase_impact.h). Either way no impact adds kinetic
// energy (impact_energy.h).
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

// One impact on `points` (pre-impact normal velocities vn) under `law` (Poisson or Stronge), with
// each point's restitution scaled by `restitution_scale`, and none below `min_bounce_speed`.
// Returns false, changing nothing, where the law cannot be followed to the end: a single point
// whose compression never ends (its normal velocity stops rising while it still approaches, as a
// slender body sliding into a rough surface can); Newton's LCP then takes the impact.
bool restitutionLawImpact(World& world, const std::vector<const Contact*>& points, const std::vector<double>& vn,
                          RestitutionLaw law, const BounceThreshold& min_bounce_speed, double restitution_scale,
                          ContactSolveStats& stats);

}  // namespace tumble
