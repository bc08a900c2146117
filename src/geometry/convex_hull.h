// Convex hull of a point cloud (3D quickhull), giving a ConvexPiece with merged coplanar faces.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

// Returns the hull, or std::nullopt with `why` filled (may be null) when the points span no volume
// (fewer than 4 points, all coincident, collinear or coplanar within a tolerance relative to the
// cloud's size) or a coordinate is NaN or infinite. Tolerances (geometry/hull_tolerance.h): a point
// within 1e-9 of the cloud's diagonal of a face is not a vertex; triangles flat within 1e-6 of the
// diagonal merge into one polygon, so faces are flat, and the piece convex, to that precision.
// Vertices keep the input order; the result depends only on the input (deterministic).
std::optional<ConvexPiece> convexHull(const std::vector<Eigen::Vector3d>& points, std::string* why);

// True when every point lies on or behind every face plane of `hull` (relative tolerance): used
// to decide whether an imported triangle mesh already is convex, or had to be hulled.
bool containsAll(const ConvexPiece& hull, const std::vector<Eigen::Vector3d>& points);

}  // namespace tumble
