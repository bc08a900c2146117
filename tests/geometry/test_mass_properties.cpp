// Mass properties against closed forms: box, corner tetrahedron, a union by the parallel-axis
// theorem, and a box far from the origin.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// A few dozen roundings of O(1) terms: 1e-12 relative leaves a margin of ~1e3 ulps.
constexpr double kExact = 1e-12;

double relativeError(const Matrix3d& a, const Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

Matrix3d boxInertia(double mass, const Vector3d& size) {
  const Vector3d s2 = size.cwiseProduct(size);
  return (mass / 12 * Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y())).asDiagonal();
}

ConvexPiece boxAt(const Vector3d& size, const Vector3d& center) {
  ConvexPiece box = makeBox(size / 2);
  box.transform(Matrix3d::Identity(), center);
  return box;
}

}  // namespace

TEST_CASE("box: m/12 (b^2 + c^2, ...)", "[mass]") {
  const Vector3d size(1.0, 0.4, 0.2);
  const double density = 7.5;
  const MassProperties mp = massProperties(makeBox(size / 2), density);
  const double mass = density * size.prod();
  CHECK(mp.mass == Approx(mass).epsilon(kExact));
  CHECK(mp.center.norm() <= kExact);
  CHECK(relativeError(mp.inertia, boxInertia(mass, size)) <= kExact);
  CHECK(volume(makeBox(size / 2)) == Approx(size.prod()).epsilon(kExact));
}

// Vertices 0, e1, e2, e3 (density 1). With x = A u over the unit simplex (A = I here):
//   V = 1/6, centroid (1/4, 1/4, 1/4), int x_i x_j = (1 + delta_ij)/120.
// About the centroid: C_ii = 1/60 - V/16 = 1/160, C_ij = 1/120 - V/16 = -1/480. Inertia
//   I = tr(C) 1 - C: I_ii = 2/160 = 1/80, I_ij = +1/480.
TEST_CASE("corner tetrahedron: V = 1/6, centroid 1/4, analytic inertia", "[mass]") {
  std::string why;
  const auto tet = convexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, &why);
  REQUIRE(tet);
  const MassProperties mp = massProperties(*tet, 1.0);
  CHECK(mp.mass == Approx(1.0 / 6).epsilon(kExact));
  CHECK((mp.center - Vector3d::Constant(0.25)).norm() <= kExact);
  Matrix3d expected = Matrix3d::Constant(1.0 / 480);
  expected.diagonal().setConstant(1.0 / 80);
  CHECK(relativeError(mp.inertia, expected) <= kExact);
}

TEST_CASE("union of two off-centre boxes: parallel-axis theorem", "[mass]") {
  // A T: crossbar 0.8 x 0.1 x 0.1 centred at (0.1, 0, 0.55), shaft 0.1 x 0.1 x 0.5 at
  // (0, 0, 0.25), shifted off the origin as a whole by (2, -1, 3).
  const Vector3d shift(2, -1, 3);
  const Vector3d s1(0.8, 0.1, 0.1), c1 = Vector3d(0.1, 0, 0.55) + shift;
  const Vector3d s2(0.1, 0.1, 0.5), c2 = Vector3d(0, 0, 0.25) + shift;
  const double rho = 1000;
  const double m1 = rho * s1.prod(), m2 = rho * s2.prod();
  const Vector3d c = (m1 * c1 + m2 * c2) / (m1 + m2);
  auto steiner = [](double m, const Vector3d& d) {
    return Matrix3d(m * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose()));
  };
  const Matrix3d expected =
      boxInertia(m1, s1) + steiner(m1, c1 - c) + boxInertia(m2, s2) + steiner(m2, c2 - c);
  const MassProperties mp = massProperties({boxAt(s1, c1), boxAt(s2, c2)}, rho);
  CHECK(mp.mass == Approx(m1 + m2).epsilon(kExact));
  CHECK((mp.center - c).norm() <= kExact * c.norm());
  CHECK(relativeError(mp.inertia, expected) <= kExact);
}

TEST_CASE("a box 1e4 m from the origin keeps 1e-9 relative accuracy", "[mass]") {
  // Integrating about the origin would cancel terms of size m |c|^2 = 1e8 m against results of
  // size m, losing 8 digits; about the mean vertex nothing cancels. 1e-9 is the contract.
  const Vector3d size(1.0, 0.5, 0.25);
  const Vector3d far(1e4, -1e4, 1e4);
  const MassProperties mp = massProperties(boxAt(size, far), 2.0);
  const double mass = 2.0 * size.prod();
  CHECK(mp.mass == Approx(mass).epsilon(1e-9));
  CHECK((mp.center - far).norm() <= 1e-9 * size.norm());
  CHECK(relativeError(mp.inertia, boxInertia(mass, size)) <= 1e-9);
}

TEST_CASE("a rotated box has inertia R I0 R^T", "[mass]") {
  const Vector3d size(0.6, 0.3, 0.1);
  const Matrix3d r = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  ConvexPiece box = makeBox(size / 2);
  box.transform(r, Vector3d(0.3, 0.2, 0.1));
  const MassProperties mp = massProperties(box, 1.0);
  const Matrix3d expected = r * boxInertia(size.prod(), size) * r.transpose();
  CHECK(relativeError(mp.inertia, expected) <= kExact);
  CHECK((mp.center - Vector3d(0.3, 0.2, 0.1)).norm() <= kExact);
}
