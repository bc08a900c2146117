// 3D quickhull (Barber, Dobkin & Huhdanpaa 1996) on doubles: the triangulated hull of a cloud.
// convex_hull.cpp turns the triangles into a ConvexPiece with merged coplanar faces.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tumble {

struct TriangleHull {
  std::vector<std::array<int, 3>> triangles;  // indices into the input, CCW seen from outside
  std::vector<std::array<int, 3>> neighbors;  // neighbors[t][i]: triangle across edge i -> i+1
  std::vector<Eigen::Vector3d> normals;       // outward unit normal of each triangle
};

// `plane_tol` (m): a point within this of a face plane is on it, never outside. Returns nullopt
// with `why` filled when the cloud spans no volume.
std::optional<TriangleHull> quickhull(const std::vector<Eigen::Vector3d>& points, double plane_tol,
                                      std::string* why);

}  // namespace tumble
