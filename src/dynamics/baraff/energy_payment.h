// Taking a numerical energy gain back from a group of moving bodies: their momenta (linear and
// angular) scaled by one factor, which keeps their directions and the sign of every relative
// velocity between them, so no contact that separated approaches after.
#pragma once

#include <vector>

#include "dynamics/world.h"

namespace tumble {

// A body's kinetic plus gravitational energy (J, zero of potential at the origin; 0 if static).
double mechanicalEnergy(const World& world, int body);

// Takes `gain` (J) from the kinetic energy of `bodies`, as far as it goes; returns what is left.
double payFrom(World& world, const std::vector<int>& bodies, double gain);

}  // namespace tumble
