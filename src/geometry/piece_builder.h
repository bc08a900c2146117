// Assembles a ConvexPiece from vertices and polygon faces: the normals and the edge list follow
// from the faces, so every producer (hull, primitives) derives them the same way.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

// Faces are counter-clockwise seen from outside. Normals come from Newell's formula (the
// area-weighted normal of the polygon, exact for planar faces and the best fit for faces flat
// only within a tolerance); edges are every undirected face edge once, sorted.
ConvexPiece buildPiece(std::vector<Eigen::Vector3d> vertices, std::vector<std::vector<int>> faces);

// Outward unit normal of one polygon by Newell's formula, about the polygon's mean so that pieces
// far from the origin lose no digits.
Eigen::Vector3d polygonNormal(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<int>& face);

}  // namespace tumble
