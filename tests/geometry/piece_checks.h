// Structural checks every ConvexPiece must pass, shared by the geometry tests.
#pragma once

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <utility>

#include "geometry/convex_piece.h"

namespace tumble::test {

inline double diagonal(const ConvexPiece& p) {
  Eigen::Vector3d lo = p.vertices.front(), hi = lo;
  for (const Eigen::Vector3d& v : p.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return (hi - lo).norm();
}

// A closed, consistently oriented, convex polyhedron: every directed edge is walked once and its
// reverse once (closed 2-manifold, CCW faces agree), V - E + F = 2, normals unit, every vertex on
// or behind every face plane, every face outward (its Newell normal agrees with the stored one).
// Tolerance: the hull merges triangles flat within 1e-6 of the diagonal (hull_tolerance.h), so a
// merged face of a random cloud may have a vertex that far off its best-fit plane.
inline void checkConvexPiece(const ConvexPiece& p) {
  REQUIRE(p.faces.size() == p.face_normals.size());
  const double tol = 1e-6 * diagonal(p);
  std::map<std::pair<int, int>, int> directed;
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const std::vector<int>& face = p.faces[f];
    REQUIRE(face.size() >= 3);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), newell = Eigen::Vector3d::Zero();
    for (int v : face) mean += p.vertices[v];
    mean /= double(face.size());
    for (size_t i = 0; i < face.size(); ++i) {
      const int a = face[i], b = face[(i + 1) % face.size()];
      ++directed[{a, b}];
      newell += (p.vertices[a] - mean).cross(p.vertices[b] - mean);
    }
    CHECK(p.face_normals[f].norm() == Approx(1).epsilon(1e-12));
    CHECK(newell.normalized().dot(p.face_normals[f]) > 1 - 1e-9);
    double highest = -1;  // one CHECK per face keeps thousand-face pieces fast to check
    for (const Eigen::Vector3d& v : p.vertices) {
      highest = std::max(highest, p.face_normals[f].dot(v - mean));
    }
    CHECK(highest <= tol);
  }
  for (const auto& [edge, count] : directed) {
    CHECK(count == 1);
    CHECK(directed.count({edge.second, edge.first}) == 1);
  }
  CHECK(p.edges.size() * 2 == directed.size());
  for (const auto& [a, b] : p.edges) CHECK(a < b);
  CHECK(int(p.vertices.size()) - int(p.edges.size()) + int(p.faces.size()) == 2);
}

}  // namespace tumble::test
