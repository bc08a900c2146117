// How large a body is, for the bounds that scale with it (the tunnelling bound, the drift
// correction's reach, the fault check's limits): computed once per body, since a piece's
// thickness costs faces x vertices.
#pragma once

#include <limits>
#include <vector>

#include "dynamics/world.h"

namespace tumble {

struct BodyExtent {
  double radius = 0;                                          // m: farthest vertex from the centre of mass
  double thinnest = std::numeric_limits<double>::infinity();  // m: thinnest piece (inf: a plane)
};

BodyExtent extentOf(const RigidBody& body);
std::vector<BodyExtent> extentsOf(const World& world);

}  // namespace tumble
