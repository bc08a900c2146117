#include "geometry/hull_tolerance.h"

#include <algorithm>
#include <limits>

namespace tumble {

HullTolerance hullTolerance(const std::vector<Eigen::Vector3d>& points) {
  HullTolerance tol;
  if (points.empty()) return tol;
  Eigen::Vector3d lo = points.front(), hi = points.front();
  double max_abs = 0;
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    max_abs = std::max(max_abs, p.cwiseAbs().maxCoeff());
  }
  const double diagonal = (hi - lo).norm();
  const double eps = std::numeric_limits<double>::epsilon();
  tol.plane = std::max(1e-9 * diagonal, 1e2 * eps * max_abs);
  tol.merge = std::max(1e-6 * diagonal, tol.plane);
  tol.contain = 2 * tol.merge;
  return tol;
}

}  // namespace tumble
