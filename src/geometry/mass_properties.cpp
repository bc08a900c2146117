// Mass properties of a solid polyhedron from its boundary.
//
// Derivation. Fan-triangulate every face and join each triangle (a, b, c) to a reference point r;
// the signed tetrahedra (r, a, b, c) tile the solid, the parts outside it cancelling (divergence
// theorem; with faces CCW from outside each volume a.(b x c)/6 is positive for a convex piece
// and r inside). For one tetrahedron with a vertex at the origin, x = A u with A = [a b c] and u
// in the unit simplex, dx = 6V du. Over the unit simplex  int du = 1/6,  int u_i du = 1/24,
// int u_i u_j du = (1 + delta_ij)/120. Hence
//   int dV = V,   int x dV = V (a + b + c)/4,
//   int x x^T dV = 6V A (I + 1 1^T)/120 A^T = V/20 (a a^T + b b^T + c c^T + s s^T),  s = a+b+c.
// Summing gives V, the first moment S and the second moment C of the solid about r. About the
// centroid d = S/V the second moment is C - V d d^T, and the inertia tensor of a uniform density
// rho is rho (tr(C) 1 - C). Taking r as the mean vertex keeps every coordinate of the size of the
// piece, so a piece 1e4 m from the origin loses no more digits than one at the origin.
#include "geometry/mass_properties.h"

#include <Eigen/Geometry>  // cross products
#include <cassert>

namespace tumble {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

struct VolumeIntegrals {
  double volume = 0;                                // int dV
  Vector3d first = Vector3d::Zero();                // int (x - r) dV
  Matrix3d second = Matrix3d::Zero();               // int (x - r)(x - r)^T dV
};

Vector3d meanVertex(const ConvexPiece& piece) {
  Vector3d mean = Vector3d::Zero();
  for (const Vector3d& v : piece.vertices) mean += v;
  return piece.vertices.empty() ? mean : Vector3d(mean / double(piece.vertices.size()));
}

VolumeIntegrals integrate(const ConvexPiece& piece, const Vector3d& r) {
  VolumeIntegrals sum;
  for (const std::vector<int>& face : piece.faces) {
    const Vector3d a = piece.vertices[face[0]] - r;
    for (size_t i = 1; i + 1 < face.size(); ++i) {
      const Vector3d b = piece.vertices[face[i]] - r;
      const Vector3d c = piece.vertices[face[i + 1]] - r;
      const Vector3d s = a + b + c;
      const double v = a.dot(b.cross(c)) / 6;
      sum.volume += v;
      sum.first += v / 4 * s;
      sum.second += v / 20 *
                    (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  return sum;
}

// Parallel-axis theorem: inertia about a point displaced by d from the centre of mass.
Matrix3d shifted(const Matrix3d& inertia, double mass, const Vector3d& d) {
  return inertia + mass * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose());
}

}  // namespace

double volume(const ConvexPiece& piece) {
  if (piece.rounded()) return roundedVolume(piece);
  if (piece.revolved()) return revolvedVolume(piece);
  return integrate(piece, meanVertex(piece)).volume;
}

MassProperties massProperties(const ConvexPiece& piece, double density) {
  assert(density > 0);
  if (piece.rounded()) return roundedMassProperties(piece, density);
  if (piece.revolved()) return revolvedMassProperties(piece, density);
  const Vector3d r = meanVertex(piece);
  const VolumeIntegrals in = integrate(piece, r);
  MassProperties mp;
  mp.center = r;
  if (!(in.volume > 0)) return mp;  // a flat or empty piece has no mass
  const Vector3d d = in.first / in.volume;
  const Matrix3d c = density * (in.second - in.volume * d * d.transpose());
  mp.mass = density * in.volume;
  mp.center = r + d;
  mp.inertia = c.trace() * Matrix3d::Identity() - c;
  return mp;
}

MassProperties massProperties(const std::vector<ConvexPiece>& pieces, double density) {
  std::vector<MassProperties> parts;
  for (const ConvexPiece& piece : pieces) parts.push_back(massProperties(piece, density));
  MassProperties total;
  if (parts.empty()) return total;
  // The centre as an offset from the first part's centre: the same digits-keeping idea as above.
  const Vector3d origin = parts.front().center;
  Vector3d moment = Vector3d::Zero();
  for (const MassProperties& p : parts) {
    total.mass += p.mass;
    moment += p.mass * (p.center - origin);
  }
  total.center = total.mass > 0 ? Vector3d(origin + moment / total.mass) : origin;
  for (const MassProperties& p : parts) {
    total.inertia += shifted(p.inertia, p.mass, p.center - total.center);
  }
  return total;
}

}  // namespace tumble
