#include "geometry/convex_piece.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

void ConvexPiece::transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (Eigen::Vector3d& v : vertices) v = R * v + t;
  for (Eigen::Vector3d& n : face_normals) n = (R * n).normalized();
}

double ConvexPiece::thickness() const {
  if (rounded()) return 2 * radius_m;   // a capsule is thinnest across its axis
  if (revolved()) {
    const double h = (vertices[1] - vertices[0]).norm(), r = disc_radius_m;
    if (revolution == Revolution::Cylinder) return std::min(2 * r, h);
    return 2 * r * h / (r + std::hypot(r, h));   // the diameter of the cone's inscribed ball
  }
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

double ConvexPiece::rollingRadius(const Eigen::Vector3d& n) const {
  if (rounded()) return radius_m;
  if (revolution != Revolution::Cylinder) return 0;
  // On its side when the normal is square to the axis, to the angle below which two directions
  // count as parallel elsewhere in the narrow phase (1e-6 rad).
  const Eigen::Vector3d axis = (vertices[1] - vertices[0]).normalized();
  return std::abs(axis.dot(n)) < 1e-6 ? disc_radius_m : 0.0;
}

Eigen::Vector3d ConvexPiece::support(const Eigen::Vector3d& d) const {
  return supportAt(vertices.data(), vertices.size(), d);
}

Eigen::Vector3d ConvexPiece::supportAt(const Eigen::Vector3d* v, std::size_t count, const Eigen::Vector3d& d) const {
  std::size_t best = 0;
  double highest = v[0].dot(d);   // each vertex's height along d once
  for (std::size_t i = 1; i < count; ++i) {
    const double h = v[i].dot(d);
    if (h > highest) best = i, highest = h;
  }
  if (rounded()) return v[best] + radius_m * d.normalized();
  if (!revolved()) return v[best];
  // The disc at an end of the axis reaches farthest along d at its rim point in d's direction
  // across the axis; a cylinder takes the end farther along d, a cone the farther of its base rim
  // point and its apex. That direction is made square to the axis once more after normalising:
  // for d nearly along the axis, one projection leaves a component along it of rounding over the
  // small remainder, and the rim point would sit that far off its disc's plane (4e-7 of the radius
  // was seen), which the support query's exactness does not survive.
  const Eigen::Vector3d axis = (v[1] - v[0]).normalized();
  Eigen::Vector3d across = d - d.dot(axis) * axis;
  const double n = across.norm();
  if (n > 1e-12 * d.norm()) {
    across /= n;
    across = (across - across.dot(axis) * axis).normalized();
  } else {
    across.setZero();
  }
  if (revolution == Revolution::Cylinder) return (d.dot(axis) >= 0 ? v[1] : v[0]) + disc_radius_m * across;
  const Eigen::Vector3d rim = v[0] + disc_radius_m * across;
  return rim.dot(d) >= v[1].dot(d) ? rim : v[1];
}

}  // namespace tumble
