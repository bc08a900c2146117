// Built-in shapes as convex pieces, centred on the origin.
#pragma once

#include <Eigen/Core>

#include "geometry/convex_piece.h"

namespace tumble {

ConvexPiece makeBox(const Eigen::Vector3d& half_extents_m);
// An icosphere (subdivided icosahedron): level 3 gives 642 vertices. Its volume is slightly below
// the sphere's; the exact sphere is a separate shape in the contact pipeline.
ConvexPiece makeIcosphere(double radius_m, int subdivisions);
// Rounded pieces (convex_piece.h): an exact sphere (a point swept by a ball of radius_m), and a
// capsule (a segment of length_m along z, centred, swept by a ball of radius_m; length 0 is a sphere).
ConvexPiece makeSphere(double radius_m);
ConvexPiece makeCapsule(double radius_m, double length_m);
// Solids of revolution about z, centred on their bounding box as Blender's primitives are: a
// cylinder (radius_m, height_m), and a cone with its base at z = -height_m/2 and its apex above.
ConvexPiece makeCylinder(double radius_m, double height_m);
ConvexPiece makeCone(double radius_m, double height_m);
// A tube: a cylinder of radius_m with a bore of inner_radius_m (< radius_m), hollow in mass only.
ConvexPiece makeTube(double radius_m, double inner_radius_m, double height_m);

}  // namespace tumble
