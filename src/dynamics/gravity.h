// The force stage: gravity acting on every moving body's centre of mass.
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

// Sets wrenches[i] to gravity's (m g, 0) for moving bodies and to zero for static ones.
void applyGravity(const World& world, std::vector<Wrench>& wrenches);

}  // namespace tumble
