#include "geometry/mesh_convexity.h"

#include <Eigen/Geometry>  // cross products

#include "geometry/hull_tolerance.h"

namespace tumble {
namespace {

using Eigen::Vector3d;

// Support queries max_v d.v over the hull's vertices by hill climbing along its edges: a linear
// function on a convex polytope has no local maximum but the global one, so from any start the
// climb ends at the answer. Starting from the last answer makes a scan over neighbouring
// triangles cost a few steps each, instead of a pass over every vertex (O(T V) on big meshes).
class SupportWalker {
 public:
  explicit SupportWalker(const ConvexPiece& hull) : hull_(hull), next_(hull.vertices.size()) {
    for (const auto& [a, b] : hull.edges) {
      next_[a].push_back(b);
      next_[b].push_back(a);
    }
  }

  double support(const Vector3d& d) {
    double best = d.dot(hull_.vertices[at_]);
    for (bool moved = true; moved;) {
      moved = false;
      for (int n : next_[at_]) {
        const double value = d.dot(hull_.vertices[n]);
        if (value > best) best = value, at_ = n, moved = true;
      }
    }
    return best;
  }

 private:
  const ConvexPiece& hull_;
  std::vector<std::vector<int>> next_;
  int at_ = 0;
};

}  // namespace

bool isConvexMesh(const std::vector<Vector3d>& points,
                  const std::vector<std::array<int, 3>>& triangles, const ConvexPiece& hull) {
  const double tol = hullTolerance(hull.vertices).contain;
  SupportWalker walker(hull);
  for (const std::array<int, 3>& t : triangles) {
    const Vector3d& a = points[t[0]];
    const Vector3d n = (points[t[1]] - a).cross(points[t[2]] - a);
    if (n.norm() == 0) continue;  // a degenerate triangle carries no surface
    const Vector3d u = n.normalized();
    // The triangle's plane supports the hull on one side or the other (either winding).
    const double d = u.dot(a);
    if (walker.support(u) - d > tol && walker.support(-u) + d > tol) return false;
  }
  return true;
}

}  // namespace tumble
