#include "app/smooth_drawing.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace tumble {

void appendRoundedMesh(const ConvexPiece& piece, int subdivisions, DrawMesh& mesh) {
  assert(piece.rounded() && !piece.vertices.empty());
  const int s = std::clamp(subdivisions, 1, 6);
  const int around = 8 << s, rings = 2 << s;   // per half: latitude bands from pole to equator
  const Eigen::Vector3d bottom = piece.vertices.front(), top = piece.vertices.back();
  Eigen::Vector3d axis = top - bottom;
  axis = axis.norm() > 0 ? Eigen::Vector3d(axis.normalized()) : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  const double r = piece.radius_m;
  // Latitude rows from the bottom pole to the top pole; the equator appears twice (once on each
  // end's half-sphere), and the band between those two rows is the capsule's cylinder.
  struct Row {
    double lat;                  // rad, -pi/2 .. pi/2
    Eigen::Vector3d centre;
  };
  std::vector<Row> rows;
  for (int i = 0; i <= rings; ++i) rows.push_back({-M_PI / 2 + M_PI / 2 * i / rings, bottom});
  for (int i = 0; i <= rings; ++i) rows.push_back({M_PI / 2 * i / rings, top});
  auto normalAt = [&](double lat, int j) {
    const double lon = 2 * M_PI * j / around;
    return Eigen::Vector3d(std::cos(lat) * (std::cos(lon) * u + std::sin(lon) * v) + std::sin(lat) * axis);
  };
  auto corner = [&](const Row& row, int j) {
    const Eigen::Vector3d n = normalAt(row.lat, j);
    mesh.positions.push_back((row.centre + r * n).cast<float>());
    mesh.normals.push_back(n.cast<float>());
  };
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const Row &lo = rows[i], &hi = rows[i + 1];
    if (lo.lat == hi.lat && (lo.centre - hi.centre).norm() == 0) continue;   // a sphere's equator twice
    for (int j = 0; j < around; ++j) {
      // counter-clockwise seen from outside: longitude grows about +axis
      if (std::cos(lo.lat) > 1e-12) corner(lo, j), corner(lo, j + 1), corner(hi, j + 1);
      if (std::cos(hi.lat) > 1e-12) corner(lo, j), corner(hi, j + 1), corner(hi, j);
    }
  }
}

void appendRevolvedMesh(const ConvexPiece& piece, int subdivisions, DrawMesh& mesh) {
  assert(piece.revolved() && piece.vertices.size() == 2);
  const int around = 8 << std::clamp(subdivisions, 1, 6);
  const Eigen::Vector3d base = piece.vertices[0], top = piece.vertices[1];
  const Eigen::Vector3d axis = (top - base).normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  const double r = piece.disc_radius_m, h = (top - base).norm();
  const bool cone = piece.revolution == ConvexPiece::Revolution::Cone;
  const double bore = piece.bore_radius_m;
  const double top_r = cone ? 0.0 : r;
  auto radial = [&](int j) {
    const double lon = 2 * M_PI * j / around;
    return Eigen::Vector3d(std::cos(lon) * u + std::sin(lon) * v);
  };
  // The side's normal leans towards the apex by the cone's half-angle: (h, r) across and along.
  const double lean = cone ? r / std::hypot(r, h) : 0.0, out = cone ? h / std::hypot(r, h) : 1.0;
  auto push = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    mesh.positions.push_back(p.cast<float>());
    mesh.normals.push_back(n.cast<float>());
  };
  for (int j = 0; j < around; ++j) {
    const Eigen::Vector3d a = radial(j), b = radial(j + 1);
    const Eigen::Vector3d na = out * a + lean * axis, nb = out * b + lean * axis;
    // side, counter-clockwise seen from outside (longitude grows about +axis)
    push(base + r * a, na), push(base + r * b, nb), push(top + top_r * b, nb);
    if (!cone) push(base + r * a, na), push(top + top_r * b, nb), push(top + top_r * a, na);
    if (bore > 0) {   // a tube: its bore's wall faces the axis, its ends are rings
      push(base + bore * a, -a), push(top + bore * b, -b), push(base + bore * b, -b);
      push(base + bore * a, -a), push(top + bore * a, -a), push(top + bore * b, -b);
      push(base + bore * a, -axis), push(base + r * b, -axis), push(base + r * a, -axis);
      push(base + bore * a, -axis), push(base + bore * b, -axis), push(base + r * b, -axis);
      push(top + bore * a, axis), push(top + r * a, axis), push(top + r * b, axis);
      push(top + bore * a, axis), push(top + r * b, axis), push(top + bore * b, axis);
      continue;
    }
    // the base disc faces -axis, the top disc +axis
    push(base, -axis), push(base + r * b, -axis), push(base + r * a, -axis);
    if (!cone) push(top, axis), push(top + r * a, axis), push(top + r * b, axis);
  }
}

}  // namespace tumble
