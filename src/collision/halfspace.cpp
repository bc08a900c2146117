// The static ground: the half-space z <= height, always body B of its pairs, so the normal from
// the piece (A) to the ground is -z. Its contact points are the piece's vertices within the margin:
// the ground has no edges or vertices of its own, so no clipping is needed.
#include <algorithm>
#include <cmath>

#include "collision/narrow_internal.h"
#include "collision/narrow_phase.h"

namespace tumble {
namespace {

// The discs of a solid of revolution (world frame): a cylinder's two ends, a cone's base; and a
// cone's apex as a disc of radius 0.
struct Disc {
  Eigen::Vector3d centre, axis;
  double radius;
};

int discsOf(const ConvexPiece& piece, const Eigen::Isometry3d& pose, Disc (&discs)[2]) {
  const Eigen::Vector3d p0 = pose * piece.vertices[0], p1 = pose * piece.vertices[1];
  const Eigen::Vector3d u = (p1 - p0).normalized();
  discs[0] = {p0, u, piece.disc_radius_m};
  discs[1] = {p1, u, piece.revolution == ConvexPiece::Revolution::Cylinder ? piece.disc_radius_m : 0.0};
  return 2;
}

// A disc's lowest rim point and the seven an eighth of a turn apart from it (narrow_internal.h,
// as support_contact.cpp takes a disc against a face): what of the rim can rest on the ground. A
// level disc has no lowest point; its points are then taken from the world's x axis across the
// disc, so that they do not turn with rounding.
using narrow::discRimPoint;
constexpr int kRimPoints = narrow::kDiscRimPoints;

void discPoints(const Disc& d, Eigen::Vector3d (&points)[kRimPoints]) {
  Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();
  Eigen::Vector3d e1 = down - down.dot(d.axis) * d.axis;
  if (e1.norm() < 1e-9) {
    e1 = Eigen::Vector3d::UnitX() - d.axis.x() * d.axis;
    if (e1.norm() < 0.5) e1 = Eigen::Vector3d::UnitY() - d.axis.y() * d.axis;
  }
  e1.normalize();
  const Eigen::Vector3d e2 = d.axis.cross(e1);
  for (int k = 0; k < kRimPoints; ++k) points[k] = discRimPoint(d.centre, e1, e2, d.radius, k);
}

bool collideRevolvedGround(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m, double margin_m,
                           ContactManifold& out) {
  Disc discs[2];
  const int n = discsOf(piece, pose, discs);
  for (int k = 0; k < n; ++k) {
    Eigen::Vector3d rim[kRimPoints];
    discPoints(discs[k], rim);
    const int count = discs[k].radius > 0 ? kRimPoints : 1;
    for (int i = 0; i < count; ++i) {
      const double z = rim[i].z();
      if (z > height_m + margin_m) continue;
      Eigen::Vector3d p = rim[i];
      p.z() = 0.5 * (z + height_m);
      out.points.push_back({p, height_m - z, std::uint32_t(kRimPoints * k + i)});
    }
  }
  narrow::reduceManifold(out.points, out.normal);
  return !out.points.empty();
}

}  // namespace

bool collideGround(const ConvexPiece& piece, const Eigen::Isometry3d& pose, double height_m,
                   double margin_m, ContactManifold& out) {
  out.normal = -Eigen::Vector3d::UnitZ();
  out.points.clear();
  out.closest_points = false;   // the ground's normal never turns
  if (piece.revolved()) return collideRevolvedGround(piece, pose, height_m, margin_m, out);
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
  if (piece.revolved()) {   // the lowest rim point, exactly
    Disc discs[2];
    const int n = discsOf(piece, pose, discs);
    double lowest = INFINITY;
    for (int k = 0; k < n; ++k) {
      const double across = std::sqrt(std::max(0.0, 1 - discs[k].axis.z() * discs[k].axis.z()));
      lowest = std::min(lowest, discs[k].centre.z() - discs[k].radius * across);
    }
    return lowest - height_m;
  }
  const Eigen::Vector3d up_in_body = pose.linear().row(2).transpose();
  double lowest = INFINITY;
  for (const Eigen::Vector3d& v : piece.vertices) lowest = std::min(lowest, up_in_body.dot(v));
  return pose.translation().z() + lowest - piece.radius_m - height_m;
}

}  // namespace tumble
