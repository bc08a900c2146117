// The force stage: gravity acting on every moving body's centre of mass, as a force over a
// (sub-)step (the Baraff model) or as the impulse of a whole step (the time-stepping model).
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

// Sets wrenches[i] to gravity's (m g, 0) for moving bodies and to zero for static ones.
void applyGravity(const World& world, std::vector<Wrench>& wrenches);
// Adds gravity's impulse over dt, m g dt, to every moving body's momentum.
void applyGravityImpulse(World& world, double dt);

}  // namespace tumble
