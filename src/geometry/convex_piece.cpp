#include "geometry/convex_piece.h"

namespace tumble {

void ConvexPiece::transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (Eigen::Vector3d& v : vertices) v = R * v + t;
  for (Eigen::Vector3d& n : face_normals) n = (R * n).normalized();
}

}  // namespace tumble
