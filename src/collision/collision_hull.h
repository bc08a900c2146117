// What the narrow phase derives once from a convex piece: it does not depend on the pose, so the
// world builds one per piece and every step reuses it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "collision/box_shape.h"
#include "geometry/convex_piece.h"

namespace tumble {

struct CollisionHull {
  const ConvexPiece* piece = nullptr;          // not owned: the piece must outlive the hull
  std::vector<std::array<int, 2>> edge_faces;  // per piece->edges[k]: the two faces meeting there
                                               // (the Gauss-map arc of the edge, for SAT pruning)
  std::vector<double> face_offsets;            // plane of face f: normal_f . x = offset_f (m)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // vertex mean: an interior point (m)
  double radius = 0;                           // max |v| about the body origin (m)
  double size = 0;                             // max extent of the vertices (m): scales tolerances
  std::optional<BoxShape> box;                 // set when the piece is a rectangular box
};

// Asserts the piece is a closed hull: every edge borders exactly two faces.
CollisionHull makeCollisionHull(const ConvexPiece& piece);
CollisionHull makeCollisionHull(const ConvexPiece&& piece) = delete;  // would dangle

}  // namespace tumble
