#include "app/piece_outline.h"

#include <cmath>

namespace tumble {
namespace {

constexpr int kCircleSegments = 24;   // a ring reads as round at any size a frame shows it

// A circle of radius r about `centre`, in the plane spanned by the unit vectors u and v.
void circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, const Eigen::Vector3d& v, double r,
            std::vector<OutlineSegment>& out) {
  auto at = [&](int k) {
    const double a = 2 * M_PI * k / kCircleSegments;
    return Eigen::Vector3d(centre + r * (std::cos(a) * u + std::sin(a) * v));
  };
  for (int k = 0; k < kCircleSegments; ++k) out.emplace_back(at(k), at(k + 1));
}

// Two unit vectors across `axis` (unit), and the axis: a frame for rings about it.
void across(const Eigen::Vector3d& axis, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  u = axis.unitOrthogonal();
  v = axis.cross(u);
}

// Four lines along the side from `a` to `b`, r off the axis, a quarter turn apart.
void sideLines(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ra, double rb, const Eigen::Vector3d& u,
               const Eigen::Vector3d& v, std::vector<OutlineSegment>& out) {
  for (const Eigen::Vector3d& d : {u, v, Eigen::Vector3d(-u), Eigen::Vector3d(-v)}) out.emplace_back(a + ra * d, b + rb * d);
}

void rounded(const ConvexPiece& p, std::vector<OutlineSegment>& out) {
  const double r = p.radius_m;
  if (p.vertices.size() < 2) {   // a sphere: three great circles
    const Eigen::Vector3d c = p.vertices.empty() ? Eigen::Vector3d::Zero() : p.vertices[0];
    circle(c, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), r, out);
    circle(c, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), r, out);
    circle(c, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), r, out);
    return;
  }
  const Eigen::Vector3d a = p.vertices[0], b = p.vertices[1];
  const Eigen::Vector3d axis = (b - a).normalized();
  Eigen::Vector3d u, v;
  across(axis, u, v);
  for (const Eigen::Vector3d& end : {a, b}) {
    circle(end, u, v, r, out);      // the ring across the axis
    circle(end, axis, u, r, out);   // and one through it: the cap's outline
  }
  sideLines(a, b, r, r, u, v, out);
}

void revolved(const ConvexPiece& p, std::vector<OutlineSegment>& out) {
  const Eigen::Vector3d a = p.vertices[0], b = p.vertices[1];
  Eigen::Vector3d u, v;
  across((b - a).normalized(), u, v);
  const double r = p.disc_radius_m;
  const bool cone = p.revolution == ConvexPiece::Revolution::Cone;
  circle(a, u, v, r, out);
  if (!cone) circle(b, u, v, r, out);
  sideLines(a, b, r, cone ? 0.0 : r, u, v, out);
}

}  // namespace

std::vector<OutlineSegment> bodyOutline(const RigidBody& body) {
  std::vector<OutlineSegment> out;
  for (const ConvexPiece& p : body.pieces) {
    if (p.rounded()) rounded(p, out);
    else if (p.revolved() && p.vertices.size() >= 2) revolved(p, out);
    else
      for (const auto& [i, j] : p.edges) out.emplace_back(p.vertices[static_cast<std::size_t>(i)], p.vertices[static_cast<std::size_t>(j)]);
  }
  return out;
}

}  // namespace tumble
