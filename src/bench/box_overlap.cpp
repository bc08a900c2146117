#include "bench/box_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::bench {

double groundDepth(const BoxPose& box) {
  // The lowest corner sits |R_z . h| below the centre (sum over axes of |R(2,k)| h_k).
  const double reach = box.R.row(2).cwiseAbs().dot(box.half_extents);
  return std::max(0.0, reach - box.x.z());
}

double boxOverlap(const BoxPose& a, const BoxPose& b) {
  const Eigen::Vector3d d = b.x - a.x;
  // Cheap rejection by bounding spheres: most pairs in a pile are far apart.
  if (d.norm() > a.half_extents.norm() + b.half_extents.norm()) return 0;
  double best = std::numeric_limits<double>::infinity();
  auto test = [&](const Eigen::Vector3d& axis) {
    const double len = axis.norm();
    // Edge pairs that are (nearly) parallel give no new direction; their face axes cover them.
    if (len < 1e-9) return;
    const Eigen::Vector3d n = axis / len;
    const double ra = (a.R.transpose() * n).cwiseAbs().dot(a.half_extents);
    const double rb = (b.R.transpose() * n).cwiseAbs().dot(b.half_extents);
    best = std::min(best, ra + rb - std::abs(d.dot(n)));
  };
  for (int i = 0; i < 3; ++i) test(a.R.col(i));
  for (int i = 0; i < 3; ++i) test(b.R.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) test(a.R.col(i).cross(b.R.col(j)));
  return std::max(0.0, best);
}

}  // namespace tumble::bench
