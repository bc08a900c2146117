// A pair's contact manifold kept between steps in the two pieces' own frames, and reused while
// their relative pose has moved less than a drift budget: the narrow phase then does not run for
// the pair. Jolt keeps a body pair's manifold the same way while the pair's relative position
// and rotation stay within a threshold (its body-pair cache); Bullet keeps each contact point on
// both bodies (its persistent manifolds) and refreshes the point's depth from them.
//
// What is kept, and why a reused manifold is exact. Each point is a pair of material points, one
// on each surface, and its depth is recomputed from where the two bodies are now, along the normal
// carried by the piece whose face it is. A vertex of one piece on the face of the other is then
// exact: the point on the face stays in the face's plane, so the depth is the vertex's distance to
// that plane (the other piece's face turns by second order). So only such manifolds are kept:
//   - the ground's: every vertex within the margin (its reduction drops only points inside the
//     support polygon);
//   - between two pieces, a face resting on a face: three or four points, each at a vertex of one
//     piece, the normal a face normal of one piece and the other piece's face turned against it
//     within the narrow phase's face-on-face angle;
//   - between two pieces, one or two vertices of one piece on a face of the other (a box resting
//     on an edge or a corner), the normal that face's, every other vertex of the first piece
//     farther than the margin above the face's plane: the other piece lies wholly under that
//     plane, so nothing else of the pair was within the margin, unreported, when it was built
//     (two in five of the narrow phases of the 1000-box pile's time-stepping run gave one or two
//     points; keeping those that qualify raised the pairs reusing their manifold from 25 % to
//     37 % and took the run 4 % less time, 2026-11-28);
//   - a pair found apart, kept as "nothing within the margin".
// What is not kept, with what it cost when it was: a point clipped at the border of the other
// piece's face (a box overhanging the one below) stays at the material point of its edge, whose
// depth drifts by the drift times the tilt (6e-6 m in a settling pile, against a contact tolerance
// of 1e-6 m); one or two points that are not such vertices (an edge clipped by a face's border,
// crossing edges, the closest points of pieces apart), or vertices with another vertex of their
// piece within the margin above the face, stand for one pair of features, and a piece rocking
// about them brings in another that was within the margin but unreported (a hull turning about
// the vertex it touched: 1.4e-5 m deep on its far side); a face meeting the other piece at an angle is where the narrow phase's own choice
// turns as the pieces settle (a tent's ridge, found as one card's thin edge face on the other
// card's face, became the bisector of the two cards a few steps later, and the tent, held along
// the stale normal, fell).
// The manifold is built at the caller's margin, as the narrow phase builds it afresh. A feature
// farther than the margin then comes no nearer than that margin less the drift: the caller bounds
// the drift by what it can afford to miss.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>

#include "collision/contact_manifold.h"
#include "geometry/convex_piece.h"

namespace tumble {

struct KeptManifold {
  static constexpr int kMaxPoints = 8;   // as many as the reduction keeps
  bool valid = false;
  // The moving piece's pose in the reference frame when built: B in A's frame for two pieces,
  // the piece in the world for the ground.
  Eigen::Isometry3d rel = Eigen::Isometry3d::Identity();
  double margin_m = 0;                                          // the margin it was built with
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // in the frame of the piece whose face it is
  bool normal_on_moving = false;                        // that piece: the moving one, else the reference
  int count = 0;                                                // 0: nothing within margin_m
  std::array<Eigen::Vector3d, kMaxPoints> on_ref, on_moving;    // surface points, own frames
  std::array<std::uint32_t, kMaxPoints> feature{};
};

// Which body of a kept pair is A (the manifold's normal points from A to B).
enum class ReferenceIs : std::uint8_t { A, B };

// An upper bound (m) on how far any point of the moving piece (within `radius_m` of its body
// origin) has moved in the reference frame since the manifold was built, its pose there now
// being `rel`: |dt| + ||dR|| r, with ||dR|| bounded by its Frobenius norm.
double keptDrift(const KeptManifold& k, const Eigen::Isometry3d& rel, double radius_m);

// Keeps `m` (found = false: nothing within margin_m) as built at these poses with margin_m. The
// pieces (body frame vertices; none for the ground) tell a point at a vertex from one clipped.
// Leaves the kept manifold invalid when it cannot be kept: more points than it holds, one or two
// points between two pieces, a point that is a vertex of neither piece, or a normal that is the
// normal of neither piece's faces.
void keepManifold(const ContactManifold& m, bool found, const Eigen::Isometry3d& pose_ref,
                  const Eigen::Isometry3d& pose_moving, const Eigen::Isometry3d& rel, ReferenceIs ref,
                  const ConvexPiece* ref_piece, const ConvexPiece& moving_piece, double margin_m,
                  KeptManifold& k);

// The kept manifold at the current poses, its points farther apart than margin_m left out;
// false when none is left.
bool reuseManifold(const KeptManifold& k, const Eigen::Isometry3d& pose_ref,
                   const Eigen::Isometry3d& pose_moving, ReferenceIs ref, double margin_m,
                   ContactManifold& out);

}  // namespace tumble
