#include "collision/kept_manifold.h"

#include <array>

#include "collision/narrow_internal.h"

namespace tumble {

double keptDrift(const KeptManifold& k, const Eigen::Isometry3d& rel, double radius_m) {
  const double moved = (rel.translation() - k.rel.translation()).norm();
  const double turned = (rel.linear() - k.rel.linear()).norm();   // Frobenius >= spectral norm
  return moved + turned * radius_m;
}

namespace {

// Whether n (the piece's body frame, unit) is the outward normal of one of its faces.
bool isFaceNormal(const ConvexPiece* piece, const Eigen::Vector3d& n) {
  if (!piece) return false;
  for (const Eigen::Vector3d& f : piece->face_normals)
    if ((f - n).squaredNorm() <= 1e-18) return true;
  return false;
}

// Whether the piece has a face whose outward normal is within the narrow phase's face-on-face
// angle of `out` (its body frame, unit).
bool hasFaceAlong(const ConvexPiece& piece, const Eigen::Vector3d& out) {
  for (const Eigen::Vector3d& f : piece.face_normals)
    if (f.dot(out) > narrow::kOppositeFaces) return true;
  return false;
}

// Whether p (the piece's body frame) is one of its vertices, to rounding of the transforms that
// took it to world and back.
bool atVertex(const ConvexPiece* piece, const Eigen::Vector3d& p) {
  if (!piece) return false;
  const double tol = 1e-9 * (1 + p.norm());
  for (const Eigen::Vector3d& v : piece->vertices)
    if ((v - p).squaredNorm() <= tol * tol) return true;
  return false;
}

// Whether every vertex of `piece` (body frame; at `pose`, world) but those at `touching` (world
// points of it, rounding aside) lies farther than `margin_m` above the plane through `on_plane`
// with outward unit normal `out` (world): then nothing of the piece but the touching vertices is
// within the margin of the face that plane holds, nor of the piece under it.
bool onlyTheseWithin(const ConvexPiece& piece, const Eigen::Isometry3d& pose, const Eigen::Vector3d& on_plane,
                     const Eigen::Vector3d& out, const Eigen::Vector3d* touching, int count, double margin_m) {
  for (const Eigen::Vector3d& v : piece.vertices) {
    const Eigen::Vector3d w = pose * v;
    bool reported = false;
    for (int i = 0; i < count; ++i) reported |= (w - touching[i]).squaredNorm() <= 1e-18 * (1 + w.squaredNorm());
    if (!reported && !((w - on_plane).dot(out) > margin_m)) return false;
  }
  return true;
}

// One or two points between two pieces, each at a vertex of one piece lying on a face of the
// other, whose normal is the manifold's, and every other vertex of the first piece farther than
// margin_m above that face's plane: which piece's face (None: not so).
enum class FaceOf { None, Reference, Moving };
FaceOf vertexOnFace(const ContactManifold& m, const Eigen::Isometry3d& pose_ref, const Eigen::Isometry3d& pose_moving,
                  ReferenceIs ref, const ConvexPiece& ref_piece, const ConvexPiece& moving_piece, double margin_m) {
  const double out_of_ref = ref == ReferenceIs::A ? 1.0 : -1.0;
  const Eigen::Vector3d out_ref = out_of_ref * m.normal;   // outward from the reference piece
  const int n = static_cast<int>(m.points.size());
  std::array<Eigen::Vector3d, 2> on_ref, on_moving;
  for (int i = 0; i < n; ++i) {
    const ContactPoint& p = m.points[static_cast<std::size_t>(i)];
    // As keepManifold puts them: A's surface depth/2 along +normal of the midpoint.
    const Eigen::Vector3d on_a = p.position + 0.5 * p.depth * m.normal, on_b = p.position - 0.5 * p.depth * m.normal;
    on_ref[i] = ref == ReferenceIs::A ? on_a : on_b;
    on_moving[i] = ref == ReferenceIs::A ? on_b : on_a;
  }
  auto atVertices = [&](const ConvexPiece& piece, const Eigen::Isometry3d& pose, const std::array<Eigen::Vector3d, 2>& points) {
    const Eigen::Isometry3d to_body = pose.inverse(Eigen::Isometry);
    for (int i = 0; i < n; ++i)
      if (!atVertex(&piece, to_body * points[i])) return false;
    return true;
  };
  // The reference piece's face, the moving piece's vertices on it.
  if (isFaceNormal(&ref_piece, pose_ref.linear().transpose() * out_ref) && atVertices(moving_piece, pose_moving, on_moving))
    return onlyTheseWithin(moving_piece, pose_moving, on_ref[0], out_ref, on_moving.data(), n, margin_m)
               ? FaceOf::Reference
               : FaceOf::None;
  // The moving piece's face, the reference piece's vertices on it.
  if (isFaceNormal(&moving_piece, -(pose_moving.linear().transpose() * out_ref)) && atVertices(ref_piece, pose_ref, on_ref))
    return onlyTheseWithin(ref_piece, pose_ref, on_moving[0], -out_ref, on_ref.data(), n, margin_m) ? FaceOf::Moving
                                                                                                     : FaceOf::None;
  return FaceOf::None;
}

}  // namespace

void keepManifold(const ContactManifold& m, bool found, const Eigen::Isometry3d& pose_ref,
                  const Eigen::Isometry3d& pose_moving, const Eigen::Isometry3d& rel, ReferenceIs ref,
                  const ConvexPiece* ref_piece, const ConvexPiece& moving_piece, double margin_m,
                  KeptManifold& k) {
  k.valid = false;
  const int n = found ? static_cast<int>(m.points.size()) : 0;
  if (n > KeptManifold::kMaxPoints) return;
  // One or two points between two pieces (an edge on a face, two edges crossing, the closest
  // points of pieces apart) stand for one feature pair only: a piece rocking about them brings
  // other features within the margin that were within it, unreported, when it was built. The
  // ground's points are every vertex within the margin, and three or more points a face's.
  // Kept, though, where the points are vertices of one piece on a face of the other and every
  // other vertex of the first stands farther than the margin above that face's plane: the second
  // piece lies wholly under the plane, so no other feature pair is within the margin to be left
  // unreported, and drift below the slack brings none within it (a box resting on an edge or a
  // corner of another, or leaning on it; one or two points came from two in five of the 1000-box
  // pile's narrow phases).
  const FaceOf face = ref_piece && (n == 1 || n == 2) && !m.closest_points
                         ? vertexOnFace(m, pose_ref, pose_moving, ref, *ref_piece, moving_piece, margin_m)
                         : FaceOf::None;
  if (ref_piece && (n == 1 || n == 2) && face == FaceOf::None) return;
  k.rel = rel;
  k.margin_m = margin_m;
  k.count = n;
  if (n > 0) {
    const Eigen::Isometry3d to_ref = pose_ref.inverse(Eigen::Isometry);
    const Eigen::Isometry3d to_moving = pose_moving.inverse(Eigen::Isometry);
    // The normal points from A to B: outward from A's face, into B's.
    const double out_of_ref = ref == ReferenceIs::A ? 1.0 : -1.0;
    const Eigen::Vector3d on_ref = to_ref.linear() * m.normal, on_moving = to_moving.linear() * m.normal;
    // Between two pieces, a face resting on a face: the normal is one piece's face normal, and
    // the other piece has a face turned against it (within the narrow phase's face-on-face
    // angle). A face meeting the other piece at an angle (a card's thin edge face against the
    // face of the card it leans on) is where the narrow phase's choice turns as the pieces
    // settle: a tent's ridge went from one card's face normal to the bisector of the two.
    if (!ref_piece) {
      k.normal = on_ref;   // the ground's
      k.normal_on_moving = false;
    } else if (face != FaceOf::None) {
      // Vertices on a face (above): the normal is that face's.
      k.normal_on_moving = face == FaceOf::Moving;
      k.normal = k.normal_on_moving ? on_moving : on_ref;
    } else if (isFaceNormal(ref_piece, out_of_ref * on_ref) && hasFaceAlong(moving_piece, -out_of_ref * on_moving)) {
      k.normal = on_ref;
      k.normal_on_moving = false;
    } else if (isFaceNormal(&moving_piece, -out_of_ref * on_moving) && hasFaceAlong(*ref_piece, out_of_ref * on_ref)) {
      k.normal = on_moving;
      k.normal_on_moving = true;
    } else {
      return;
    }
    for (int i = 0; i < n; ++i) {
      const ContactPoint& p = m.points[static_cast<std::size_t>(i)];
      // A's surface lies depth/2 along +normal of the midpoint, B's depth/2 against it.
      const Eigen::Vector3d on_a = p.position + 0.5 * p.depth * m.normal;
      const Eigen::Vector3d on_b = p.position - 0.5 * p.depth * m.normal;
      const bool a_is_ref = ref == ReferenceIs::A;
      k.on_ref[i] = to_ref * (a_is_ref ? on_a : on_b);
      k.on_moving[i] = to_moving * (a_is_ref ? on_b : on_a);
      k.feature[i] = p.feature;
      if (n > 1 && !atVertex(ref_piece, k.on_ref[i]) && !atVertex(&moving_piece, k.on_moving[i])) return;
    }
  }
  k.valid = true;
}

bool reuseManifold(const KeptManifold& k, const Eigen::Isometry3d& pose_ref,
                   const Eigen::Isometry3d& pose_moving, ReferenceIs ref, double margin_m,
                   ContactManifold& out) {
  out.points.clear();
  if (k.count == 0) return false;
  out.normal = (k.normal_on_moving ? pose_moving.linear() : pose_ref.linear()) * k.normal;
  out.closest_points = false;   // a closest-points manifold has one point: never kept
  for (int i = 0; i < k.count; ++i) {
    const Eigen::Vector3d p_ref = pose_ref * k.on_ref[i];
    const Eigen::Vector3d p_moving = pose_moving * k.on_moving[i];
    const Eigen::Vector3d& on_a = ref == ReferenceIs::A ? p_ref : p_moving;
    const Eigen::Vector3d& on_b = ref == ReferenceIs::A ? p_moving : p_ref;
    ContactPoint p;
    p.depth = (on_a - on_b).dot(out.normal);
    if (p.depth < -margin_m) continue;
    p.position = 0.5 * (on_a + on_b);
    p.feature = k.feature[i];
    out.points.push_back(p);
  }
  return !out.points.empty();
}

}  // namespace tumble
