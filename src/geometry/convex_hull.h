// Convex hull of a point cloud (3D quickhull), giving a ConvexPiece with merged coplanar faces.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

// Returns the hull, or std::nullopt with `why` filled when the points span no volume (fewer than
// 4 points, all collinear or coplanar within a tolerance relative to the cloud's size).
std::optional<ConvexPiece> convexHull(const std::vector<Eigen::Vector3d>& points, std::string* why);

// True when every point lies on or behind every face plane of `hull` (relative tolerance): used
// to decide whether an imported triangle mesh already is convex, or had to be hulled.
bool containsAll(const ConvexPiece& hull, const std::vector<Eigen::Vector3d>& points);

}  // namespace tumble
