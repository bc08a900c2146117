// The static ground: the half-space z <= height, always body B of its pairs, so the normal from
// the piece (A) to the ground is -z. Its contact points are the piece's vertices within the margin:
// the ground has no edges or vertices of its own, so no clipping is needed.
#include <algorithm>

#include "collision/narrow_internal.h"
#include "collision/narrow_phase.h"

namespace tumble {

bool collideGround(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m,
                   double margin_m, ContactManifold& out) {
  out.normal = -Eigen::Vector3d::UnitZ();
  out.points.clear();
  out.closest_points = false;   // the ground's normal never turns
  // world z of a vertex is t_z + (row z of R) . v: one dot product per vertex
  const Eigen::Vector3d up_in_body = pose.linear().row(2).transpose();
  const double tz = pose.translation().z();
  // A rounded piece's lowest points are its core's vertices lowered by its radius.
  const double r = piece.radius_m;
  for (size_t i = 0; i < piece.vertices.size(); ++i) {
    const double z = tz + up_in_body.dot(piece.vertices[i]) - r;
    if (z > height_m + margin_m) continue;
    Eigen::Vector3d p = pose * piece.vertices[i];
    p.z() = 0.5 * (z + height_m);   // (x, y) of the core vertex: straight above its lowest point
    out.points.push_back({p, height_m - z, std::uint32_t(i)});
  }
  narrow::reduceManifold(out.points, out.normal);
  return !out.points.empty();
}

std::optional<ContactManifold> collideGround(const ConvexPiece& piece,
                                             const Eigen::Isometry3d& pose, double height_m,
                                             double margin_m) {
  ContactManifold m;
  if (!collideGround(piece, pose, height_m, margin_m, m)) return std::nullopt;
  return m;
}

double groundSeparation(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m) {
  const Eigen::Vector3d up_in_body = pose.linear().row(2).transpose();
  double lowest = INFINITY;
  for (const Eigen::Vector3d& v : piece.vertices) lowest = std::min(lowest, up_in_body.dot(v));
  return pose.translation().z() + lowest - piece.radius_m - height_m;
}

}  // namespace tumble
