// Contact pipeline steps 4-5 of the Baraff model: classify contacts by their normal relative
// velocity, and resolve the colliding ones with impulses (Newton's restitution law, propagated pair
// by pair with each pair's points solved together: impulse_propagation.h).
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

enum class ContactClass { Separating, Resting, Colliding };

// Touching contacts (|depth| within tolerance) only; others are Separating.
ContactClass classify(const World& world, const Contact& c, const ContactSettings& settings);

// Applies restitution impulses to every colliding contact and passes them on through the touching
// contacts around them (a flat face landing on 4 corners is one impact, solved at once; a chain of
// balls passes it on ball by ball). Returns true if any contact was colliding.
// Impacts slower than `min_bounce_speed` along their normal get no restitution, and lift-offs too short for a
// step of `dt` to follow settle (contact_solve_common.h).
bool resolveCollisions(World& world, const std::vector<Contact>& contacts,
                       const ContactSettings& settings, const BounceThreshold& min_bounce_speed, double dt,
                       ContactSolveStats& stats);

}  // namespace tumble
