// Helpers shared by the collision tests.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "collision/contact_manifold.h"

namespace tumble::test {

inline Eigen::Isometry3d pose(const Eigen::Vector3d& t,
                              const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = q.toRotationMatrix();
  p.translation() = t;
  return p;
}

inline Eigen::Quaterniond rotation(double angle_rad, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, axis.normalized()));
}

inline bool allFinite(const Eigen::Vector3d& v) { return v.allFinite(); }

// The deepest point of a manifold (m; -infinity when it has none): what decides whether a pair touches.
inline double deepestDepth(const ContactManifold& m) {
  double d = -INFINITY;
  for (const ContactPoint& p : m.points) d = std::max(d, p.depth);
  return d;
}

}  // namespace tumble::test
