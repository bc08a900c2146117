// Built-in shapes as convex pieces, centred on the origin.
#pragma once

#include <Eigen/Core>

#include "geometry/convex_piece.h"

namespace tumble {

ConvexPiece makeBox(const Eigen::Vector3d& half_extents_m);
// An icosphere (subdivided icosahedron): level 3 gives 642 vertices. Its volume is slightly below
// the sphere's; the exact sphere is a separate shape in the contact pipeline.
ConvexPiece makeIcosphere(double radius_m, int subdivisions);

}  // namespace tumble
