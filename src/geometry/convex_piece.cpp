#include "geometry/convex_piece.h"

#include <algorithm>
#include <limits>

namespace tumble {

void ConvexPiece::transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (Eigen::Vector3d& v : vertices) v = R * v + t;
  for (Eigen::Vector3d& n : face_normals) n = (R * n).normalized();
}

double ConvexPiece::thickness() const {
  if (rounded()) return 2 * radius_m;   // a capsule is thinnest across its axis
  double thinnest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& n : face_normals) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::Vector3d& v : vertices) {
      lo = std::min(lo, n.dot(v));
      hi = std::max(hi, n.dot(v));
    }
    thinnest = std::min(thinnest, hi - lo);
  }
  return thinnest;
}

}  // namespace tumble
