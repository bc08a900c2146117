#include "collision/aabb.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tumble {

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() &&  //
         a.min.y() <= b.max.y() && b.min.y() <= a.max.y() &&  //
         a.min.z() <= b.max.z() && b.min.z() <= a.max.z();
}

Aabb merged(const Aabb& a, const Aabb& b) {
  return {a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)};
}

Aabb inflated(const Aabb& box, double by_m) {
  const Eigen::Vector3d d = Eigen::Vector3d::Constant(by_m);
  return {box.min - d, box.max + d};
}

namespace {

// A disc of radius r about the unit axis u reaches r sqrt(1 - u_i^2) along world axis i; a cylinder
// is its two end discs' box, a cone its base disc's and its apex's.
Aabb revolvedAabb(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double margin_m) {
  const Eigen::Vector3d p0 = pose * piece.vertices[0], p1 = pose * piece.vertices[1];
  const Eigen::Vector3d u = (p1 - p0).normalized();
  Eigen::Vector3d reach;
  for (int i = 0; i < 3; ++i) reach[i] = piece.disc_radius_m * std::sqrt(std::max(0.0, 1 - u[i] * u[i]));
  Aabb box{p0 - reach, p0 + reach};
  if (piece.revolution == ConvexPiece::Revolution::Cylinder) box = merged(box, {p1 - reach, p1 + reach});
  else box = merged(box, {p1, p1});
  return inflated(box, margin_m);
}

}  // namespace

Aabb aabbOf(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double margin_m) {
  assert(!piece.vertices.empty());
  if (piece.revolved()) return revolvedAabb(piece, pose, margin_m);
  // Each world coordinate is t_i + row_i(R) . v, so per axis only the extreme of row_i(R) . v is
  // needed: rotate once per vertex, no Isometry product (which would also touch the last row).
  const Eigen::Matrix3d R = pose.linear();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-INFINITY);
  for (const Eigen::Vector3d& v : piece.vertices) {
    const Eigen::Vector3d w = R * v;
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  return inflated({lo + pose.translation(), hi + pose.translation()}, margin_m + piece.radius_m);
}

double pieceRadius(const ConvexPiece& piece) {
  double r2 = 0;
  for (const Eigen::Vector3d& v : piece.vertices) r2 = std::max(r2, v.squaredNorm());
  return std::sqrt(r2) + piece.radius_m + piece.disc_radius_m;   // a disc's rim: at most its radius farther
}

double rotationAngle(const Eigen::Isometry3d& pose0, const Eigen::Isometry3d& pose1) {
  const Eigen::Matrix3d rel = pose1.linear() * pose0.linear().transpose();
  // angle from the trace; clamped because rounding can push the cosine just past +-1.
  const double c = std::clamp((rel.trace() - 1) / 2, -1.0, 1.0);
  return std::acos(c);
}

// Why the swept box is conservative. A body point p (|p| <= r, r = pieceRadius) sits at
//   q(s) = x(s) + R(s) p,  s in [0, 1],  with x(s) = (1-s) x0 + s x1.
// Write q(s) = (1-s) q0 + s q1 + e(s) with q0 = x0 + R0 p, q1 = x1 + R1 p. The x terms cancel:
//   e(s) = R(s)p - (1-s) R0 p - s R1 p = (1-s) (R(s)p - R0 p) + s (R(s)p - R1 p).
// A chord is never longer than the arc it spans, and p's path on the sphere |.| = |p| has length at
// most |p| * theta_turned, so |R(s)p - R0 p| <= r * s * turn and |R(s)p - R1 p| <= r (1-s) turn:
//   |e(s)| <= 2 s (1-s) r turn <= r turn / 2.
// Also |e(s)| <= |R(s)p| + |(1-s) R0 p + s R1 p| <= 2 r whatever the rotation did.
// (1-s) q0 + s q1 lies in the box of box0 U box1 (boxes are convex), so inflating that box by
// r * min(turn / 2, 2) holds q(s). We inflate by r * min(turn, 2): the factor 2 over the proof
// absorbs an integrator whose translation within the step is not exactly the straight segment
// (RK4, gyroscopic precession), at the price of a slightly larger box for fast spinners only.
Aabb sweptAabb(const ConvexPiece& piece, const Eigen::Isometry3d& pose0,
               const Eigen::Isometry3d& pose1, double turn_rad, double margin_m) {
  assert(turn_rad >= 0);
  const Aabb both = merged(aabbOf(piece, pose0, 0), aabbOf(piece, pose1, 0));
  const double grow = pieceRadius(piece) * std::min(turn_rad, 2.0);
  return inflated(both, grow + margin_m);
}

}  // namespace tumble
