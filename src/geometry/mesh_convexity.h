// Whether a triangle mesh already is its own convex hull (so importing it loses nothing).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

// True when every non-degenerate triangle lies in a supporting plane of `hull` (the hull of
// `points`): then the surface is the hull's. A dent puts some triangle's plane through the hull's
// interior. Winding is ignored: the hull replaces the mesh's own faces anyway.
bool isConvexMesh(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<std::array<int, 3>>& triangles, const ConvexPiece& hull);

}  // namespace tumble
