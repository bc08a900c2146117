// Axis-aligned bounding boxes of convex pieces: what the broad phase sorts, and the swept box that
// bounds a piece's motion over one step so that a collision inside the step is never skipped
// (docs/architecture.md, detection and back-stepping).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/convex_piece.h"

namespace tumble {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();  // m, world
  Eigen::Vector3d max = Eigen::Vector3d::Zero();  // m, world
};

// Closed intervals on all three axes: boxes that only touch overlap (a resting contact has
// separation 0 and must reach the narrow phase).
bool overlaps(const Aabb& a, const Aabb& b);
Aabb merged(const Aabb& a, const Aabb& b);
Aabb inflated(const Aabb& box, double by_m);

// Tight box of the piece's hull vertices (a rounded piece's core grown by its radius) at `pose` (body frame -> world), grown by margin_m.
Aabb aabbOf(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double margin_m);

// max |v| over the hull vertices (plus a rounded piece's radius): the radius of the ball about the body origin (the centre of mass)
// that holds the piece, whatever its orientation.
double pieceRadius(const ConvexPiece& piece);

// The angle (rad, in [0, pi]) of the rotation that takes pose0's orientation to pose1's.
double rotationAngle(const Eigen::Isometry3d& pose0, const Eigen::Isometry3d& pose1);

// A box holding the piece at every instant of a step from pose0 to pose1, grown by margin_m.
// The motion model: the origin moves on the straight segment (x0 -> x1) and the orientation turns
// through at most `turn_rad` in total (|omega| dt for a constant omega; rotationAngle(pose0, pose1)
// when the step turns less than pi). Proof of conservativeness in aabb.cpp.
Aabb sweptAabb(const ConvexPiece& piece, const Eigen::Isometry3d& pose0,
               const Eigen::Isometry3d& pose1, double turn_rad, double margin_m);

}  // namespace tumble
