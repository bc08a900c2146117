// Built-in shapes, made directly (not through the hull) so their topology is exact by
// construction: a box is 8 vertices and 6 quads, an icosphere keeps every triangle.
#include "geometry/primitives.h"

#include <Eigen/Geometry>  // cross products
#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <utility>

#include "geometry/piece_builder.h"

namespace tumble {
namespace {

using Eigen::Vector3d;
using Triangle = std::array<int, 3>;

// The icosahedron's 12 vertices are the cyclic permutations of (0, +-1, +-phi), phi the golden
// ratio, with edges of length 2. Its 20 faces are exactly the vertex triples that are pairwise
// 2 apart; each is turned CCW seen from outside (normal along its centroid).
void icosahedron(std::vector<Vector3d>& v, std::vector<Triangle>& t) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  v.clear();
  t.clear();
  for (int axis = 0; axis < 3; ++axis) {
    for (double s1 : {-1.0, 1.0}) {
      for (double s2 : {-phi, phi}) {
        Vector3d p = Vector3d::Zero();
        p[(axis + 1) % 3] = s1;
        p[(axis + 2) % 3] = s2;
        v.push_back(p);
      }
    }
  }
  auto edge = [&](int a, int b) { return std::abs((v[a] - v[b]).norm() - 2) < 1e-9; };
  for (int a = 0; a < 12; ++a) {
    for (int b = a + 1; b < 12; ++b) {
      for (int c = b + 1; c < 12; ++c) {
        if (!edge(a, b) || !edge(b, c) || !edge(a, c)) continue;
        const Vector3d n = (v[b] - v[a]).cross(v[c] - v[a]);
        t.push_back(n.dot(v[a] + v[b] + v[c]) > 0 ? Triangle{a, b, c} : Triangle{a, c, b});
      }
    }
  }
  assert(t.size() == 20);
  for (Vector3d& p : v) p.normalize();
}

// Splits each triangle into four at its edge midpoints (pushed out to the unit sphere); a shared
// edge makes its midpoint once, so the mesh stays closed: V' = V + E, F' = 4F.
void subdivide(std::vector<Vector3d>& v, std::vector<Triangle>& t) {
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, made] = midpoint.emplace(key, int(v.size()));
    if (made) v.push_back((v[a] + v[b]).normalized());
    return it->second;
  };
  std::vector<Triangle> finer;
  finer.reserve(4 * t.size());
  for (const Triangle& f : t) {
    const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    finer.push_back({f[0], ab, ca});
    finer.push_back({f[1], bc, ab});
    finer.push_back({f[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  t = std::move(finer);
}

}  // namespace

ConvexPiece makeBox(const Eigen::Vector3d& h) {
  assert((h.array() > 0).all());
  std::vector<Vector3d> v;
  for (int i = 0; i < 8; ++i) {  // bit 0: +x, bit 1: +y, bit 2: +z
    v.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
  }
  // -x, +x, -y, +y, -z, +z; each CCW seen from outside.
  std::vector<std::vector<int>> faces{{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                      {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  ConvexPiece box = buildPiece(std::move(v), std::move(faces));
  box.name = "box";
  return box;
}

ConvexPiece makeIcosphere(double radius_m, int subdivisions) {
  assert(radius_m > 0 && subdivisions >= 0);
  std::vector<Vector3d> v;
  std::vector<Triangle> t;
  icosahedron(v, t);
  for (int i = 0; i < subdivisions; ++i) subdivide(v, t);
  for (Vector3d& p : v) p *= radius_m;
  // No two triangles of an icosphere are coplanar, so each triangle is a face.
  std::vector<std::vector<int>> faces;
  for (const Triangle& f : t) faces.emplace_back(f.begin(), f.end());
  ConvexPiece sphere = buildPiece(std::move(v), std::move(faces));
  sphere.name = "icosphere";
  return sphere;
}

ConvexPiece makeSphere(double radius_m) {
  assert(radius_m > 0);
  ConvexPiece sphere;
  sphere.name = "sphere";
  sphere.vertices = {Vector3d::Zero()};
  sphere.radius_m = radius_m;
  return sphere;
}

ConvexPiece makeCapsule(double radius_m, double length_m) {
  assert(radius_m > 0 && length_m >= 0);
  if (length_m == 0) return makeSphere(radius_m);
  ConvexPiece capsule;
  capsule.name = "capsule";
  capsule.vertices = {Vector3d(0, 0, -length_m / 2), Vector3d(0, 0, length_m / 2)};
  capsule.edges = {{0, 1}};
  capsule.radius_m = radius_m;
  return capsule;
}

namespace {

ConvexPiece revolution(ConvexPiece::Revolution kind, double radius_m, double height_m, const char* name) {
  assert(radius_m > 0 && height_m > 0);
  ConvexPiece piece;
  piece.name = name;
  piece.vertices = {Vector3d(0, 0, -height_m / 2), Vector3d(0, 0, height_m / 2)};
  piece.edges = {{0, 1}};
  piece.revolution = kind;
  piece.disc_radius_m = radius_m;
  return piece;
}

}  // namespace

ConvexPiece makeCylinder(double radius_m, double height_m) {
  return revolution(ConvexPiece::Revolution::Cylinder, radius_m, height_m, "cylinder");
}

ConvexPiece makeTube(double radius_m, double inner_radius_m, double height_m) {
  assert(inner_radius_m >= 0 && inner_radius_m < radius_m);
  ConvexPiece tube = revolution(ConvexPiece::Revolution::Cylinder, radius_m, height_m, "tube");
  tube.bore_radius_m = inner_radius_m;
  return tube;
}

ConvexPiece makeCone(double radius_m, double height_m) {
  return revolution(ConvexPiece::Revolution::Cone, radius_m, height_m, "cone");
}

}  // namespace tumble
