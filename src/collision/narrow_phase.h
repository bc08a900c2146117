// Narrow phase: contact manifolds between pairs of convex pieces by the separating-axis test
// (docs/architecture.md, narrow phase; Yang, "Rigid Bodies and Contacts", 2020: "separating plane", "defining face/edge").
//
// Conventions:
//   normal   unit, world, pointing from A to B (B is pushed along +normal).
//   depth    > 0 penetrating, < 0 separated; pairs separated by more than `margin` give no contact.
//   position midway between the two surfaces.
//   ground   the half-space z <= height is always B, the piece A: normal = (0, 0, -1).
// The manifold is built by clipping the incident face against the reference face (face contacts)
// or is the single closest point of two edges (edge contacts), then reduced to 4 points (up to 8
// where four would lose much of the support polygon: manifold_reduce.cpp).
// Separated pieces closest at a vertex or an edge's end, whose distance (GJK) exceeds every tested
// axis's gap, get instead one point at their closest points, along the direction between them,
// with the true distance (ContactManifold::closest_points); pieces farther than the margin, none.
// Its deepest point is as deep as separation() says, within 1e-9 of the smaller piece's size, for
// every overlapping pair, and it never reports a penetration for a pair separation() sees apart:
// back-stepping and the projection see penetration only through it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>

#include "collision/collision_hull.h"
#include "collision/contact_manifold.h"
#include "geometry/convex_piece.h"

namespace tumble {

// Per piece pair, kept between steps: the last separating (or least penetrating) axis — the
// seed's "defining face/edge" — is tried first, and while it still separates the pair the test
// stops there. For touching pairs it keeps the reference face from flickering between near ties.
struct SatCache {
  enum class Axis : std::uint8_t { None, FaceA, FaceB, Edges };
  Axis axis = Axis::None;
  int index_a = -1;  // face of A (FaceA) or edge of A (Edges)
  int index_b = -1;  // face of B (FaceB) or edge of B (Edges)
  // What the last call did with the cached axis (for tests and --stats).
  //   EarlyExit: the cached axis still separates by more than the margin; nothing else was tested.
  //   Reused:    all axes were tested and the contact was built on the cached feature again.
  //   Miss:      anything else.
  enum class Use : std::uint8_t { Miss, EarlyExit, Reused };
  Use last_use = Use::Miss;
  std::uint32_t early_exits = 0;  // calls that the cached axis alone settled
};

// Contacts between A and B, or nothing when they are separated by more than margin_m (m).
// Writes into `out` (its point buffer is reused) and returns false when there is no contact.
bool collide(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
             const Eigen::Isometry3d& pose_b, double margin_m, SatCache& cache,
             ContactManifold& out);
std::optional<ContactManifold> collide(const CollisionHull& a, const Eigen::Isometry3d& pose_a,
                                       const CollisionHull& b, const Eigen::Isometry3d& pose_b,
                                       double margin_m, SatCache& cache);
// Convenience for tools and tests: derives the hulls on every call (slower).
std::optional<ContactManifold> collide(const ConvexPiece& a, const Eigen::Isometry3d& pose_a,
                                       const ConvexPiece& b, const Eigen::Isometry3d& pose_b,
                                       double margin_m, SatCache& cache);

// The SAT value (m): the largest separation along the tested axes (face normals of both, and the
// edge x edge axes that are faces of the Minkowski difference). > 0 separated.
// Each axis's projection gap is at most the true distance, so when separated this is a lower
// bound on the distance (equal to it for face-vertex and edge-edge closest features): safe for
// conservative advancement. When overlapping it is minus the penetration depth.
double separation(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                  const Eigen::Isometry3d& pose_b, SatCache& cache);
// The same, and the axis it was found on (world, unit, pointing from A to B): along a fixed axis
// the gap closes no faster than the two pieces' point speeds along it, so conservative advancement
// may bound a step by the approach along this axis rather than by the pieces' whole speeds.
// The axis is zero when no axis was valid (degenerate pieces).
double separation(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                  const Eigen::Isometry3d& pose_b, SatCache& cache, Eigen::Vector3d& axis);

// The distance (m, 0 when they overlap) between A and B and a closest point of each (world), by
// GJK (distance.cpp): for separated pieces within rounding of their size (1e-9 m on pieces of
// metres, which can be far more than the gap of a small face lying a hair above a large one); for
// overlapping ones the points mean nothing.
struct PieceDistance {
  double distance = 0;
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero(), point_b = Eigen::Vector3d::Zero();
};
PieceDistance pieceDistance(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                            const Eigen::Isometry3d& pose_b);

// The static ground z <= height_m (world z up). The piece is A, the ground B, so the normal is
// (0, 0, -1); every vertex below height_m + margin_m is a contact with depth = height_m - z,
// placed midway (z + height_m) / 2; then reduced keeping the support polygon.
bool collideGround(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m,
                   double margin_m, ContactManifold& out);
std::optional<ContactManifold> collideGround(const ConvexPiece& piece,
                                             const Eigen::Isometry3d& pose, double height_m,
                                             double margin_m);
// min vertex z - height_m (m): the exact distance to the ground when positive.
double groundSeparation(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m);

}  // namespace tumble
