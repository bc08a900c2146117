// A piece that is a rectangular box, recognised once from its hull: its three axes as faces and its
// twelve edges by direction and corner, so that the separating-axis test of two boxes can take the
// nine edge directions' axes from the boxes' half extents (box_sat.cpp) instead of testing every
// pair of their edges on the Gauss map.
#pragma once

#include <array>
#include <optional>

#include "geometry/convex_piece.h"

namespace tumble {

struct BoxShape {
  std::array<int, 3> plus_face{}, minus_face{};   // the face whose outward normal is +axis k / -axis k
  std::array<double, 3> half{};                   // half extent along axis k (m)
  // The edge along axis k at the corner on the + (1) or - (0) side of each of the two other axes,
  // taken in increasing order (axis 0's edges by axes 1 and 2, axis 1's by 0 and 2, axis 2's by 0 and 1).
  std::array<std::array<std::array<int, 2>, 2>, 3> edge{};
};

// The two axes other than k, in increasing order: the order BoxShape::edge files corners by.
constexpr std::array<int, 2> otherAxes(int k) { return {k == 0 ? 1 : 0, k == 2 ? 1 : 2}; }

// The box, if `piece` is one: 8 vertices, 6 four-sided faces in three opposite pairs whose normals
// are orthogonal, every vertex at a corner of the box the faces bound to within rounding. A
// parallelepiped, a mesh box whose corners were written to a few decimals, or anything else is not
// (the general test takes them).
std::optional<BoxShape> recogniseBox(const ConvexPiece& piece, const Eigen::Vector3d& centre);

}  // namespace tumble
