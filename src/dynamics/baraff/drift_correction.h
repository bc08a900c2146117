// The Baraff model's drift correction: residual penetration deeper than the tolerance is removed
// by moving and turning the two bodies of each pair, the smallest displacement (weighted by mass
// and inertia) that lifts the pair's too-deep points back within the tolerance
// (position_projection.h). Only positions move, never velocities, so no kinetic energy is added
// (unlike a Baumgarte term, which pushes bodies apart with speed).
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// Projects every pair of bodies with a contact deeper than `tolerance_m`, once per pair with all
// its points together, in the order their first too-deep point appears in `contacts`. Returns the
// number of pairs moved (their contacts are then stale).
int correctPenetration(World& world, const std::vector<Contact>& contacts, double tolerance_m);

}  // namespace tumble
