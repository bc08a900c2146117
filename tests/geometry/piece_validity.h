// What "a valid convex piece" means, as a plain function (no Catch2), so that code running outside
// a test case can use it: the child processes of the assimp model walk and the fuzz targets.
// piece_checks.h states the same rules as Catch2 CHECKs, one per property, for readable failures.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "geometry/convex_piece.h"

namespace tumble::test {

// "" when `p` is a closed, consistently oriented convex polyhedron with finite vertices, unit
// outward normals, every vertex on or behind every face plane (1e-6 of the diagonal, the hull's
// merge tolerance) and Euler characteristic 2; otherwise the first rule it breaks.
inline std::string convexPieceProblem(const ConvexPiece& p) {
  if (p.vertices.size() < 4) return "fewer than 4 vertices";
  if (p.faces.size() < 4 || p.faces.size() != p.face_normals.size()) return "too few faces or normals";
  Eigen::Vector3d lo = p.vertices.front(), hi = lo;
  for (const Eigen::Vector3d& v : p.vertices) {
    if (!v.allFinite()) return "a vertex is not finite";
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double tol = 1e-6 * (hi - lo).norm();
  if (!(tol > 0)) return "the piece has no extent";
  std::map<std::pair<int, int>, int> directed;
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& face = p.faces[f];
    if (face.size() < 3) return "a face with fewer than 3 vertices";
    if (std::abs(p.face_normals[f].norm() - 1) > 1e-9) return "a face normal is not unit length";
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : face) {
      if (v < 0 || v >= int(p.vertices.size())) return "a face index is out of range";
      mean += p.vertices[v];
    }
    mean /= double(face.size());
    for (size_t i = 0; i < face.size(); ++i) ++directed[{face[i], face[(i + 1) % face.size()]}];
    for (const Eigen::Vector3d& v : p.vertices)
      if (p.face_normals[f].dot(v - mean) > tol) return "a vertex lies in front of a face (not convex)";
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return "a directed edge is walked twice (faces disagree in orientation)";
    if (!directed.count({edge.second, edge.first})) return "an edge has one face only (not closed)";
  }
  if (p.edges.size() * 2 != directed.size()) return "the edge list does not match the faces";
  if (int(p.vertices.size()) - int(p.edges.size()) + int(p.faces.size()) != 2)
    return "Euler characteristic is not 2";
  return "";
}

}  // namespace tumble::test
