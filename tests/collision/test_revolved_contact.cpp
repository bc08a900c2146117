// Solids of revolution (cylinders, cones; collision/support_contact.cpp and the ground in
// halfspace.cpp) against closed forms: a can standing on a box holds its base at points around its
// rim, lying it holds its length, tilted it touches at its rim's lowest point; a cone on its base
// and on its apex; a ball beside a cylinder. Tolerance 1e-9 m: the support query is exact to
// 1e-12 of the size, so anything near 1e-9 on 1 m pieces is an error.
#include <catch2/catch.hpp>

#include <cmath>

#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;

namespace {

constexpr double kExact = 1e-9;   // m: the query is exact to 1e-12 of the size

double deepest(const ContactManifold& m) {
  double d = -INFINITY;
  for (const ContactPoint& p : m.points) d = std::max(d, p.depth);
  return d;
}

const ConvexPiece kBox = makeBox({0.5, 0.5, 0.5});   // top face at z = 0.5
const Eigen::Quaterniond kLying(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()));   // axis along -y

}  // namespace

TEST_CASE("a can standing on a box holds its base: points around its rim, equally deep", "[narrow][revolved]") {
  const ConvexPiece can = makeCylinder(0.05, 0.12);
  const CollisionHull hb = makeCollisionHull(kBox), hc = makeCollisionHull(can);
  for (const bool swapped : {false, true}) {
    SatCache cache;
    ContactManifold m;
    const Eigen::Isometry3d pc = pose({0.1, -0.05, 0.56 - 1e-7});
    REQUIRE((swapped ? collide(hc, pc, hb, pose(Vector3d::Zero()), 1e-3, cache, m)
                     : collide(hb, pose(Vector3d::Zero()), hc, pc, 1e-3, cache, m)));
    REQUIRE(m.points.size() == 8);
    CHECK((m.normal - (swapped ? -1.0 : 1.0) * Vector3d::UnitZ()).norm() < kExact);
    double spread = 0;
    for (const ContactPoint& p : m.points) {
      CHECK(p.depth == Approx(1e-7).margin(kExact));
      CHECK((Eigen::Vector2d(p.position.x(), p.position.y()) - Eigen::Vector2d(0.1, -0.05)).norm() ==
            Approx(0.05).margin(kExact));
      spread = std::max(spread, (p.position - m.points[0].position).norm());
    }
    CHECK(spread == Approx(0.1).margin(kExact));   // two of them across a diameter: a base, not a point
    CHECK_FALSE(m.closest_points);
  }
}

TEST_CASE("a cylinder lying on a box holds its length, and tilted its rim's lowest point", "[narrow][revolved]") {
  const ConvexPiece roller = makeCylinder(0.1, 0.3);
  const CollisionHull hb = makeCollisionHull(kBox), hc = makeCollisionHull(roller);
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(hb, pose(Vector3d::Zero()), hc, pose({0.1, 0, 0.6 - 2e-7}, kLying), 1e-3, cache, m));
  REQUIRE(m.points.size() == 2);
  for (const ContactPoint& p : m.points) CHECK(p.depth == Approx(2e-7).margin(kExact));
  CHECK(std::abs(m.points[0].position.y() - m.points[1].position.y()) == Approx(0.3).margin(kExact));
  // Standing, tilted by 0.2 rad about x: the lowest rim point is r sin(0.2) + (h/2) cos(0.2) below
  // the centre.
  const double tilt = 0.2, r = 0.1, h = 0.3;
  const double reach = r * std::sin(tilt) + h / 2 * std::cos(tilt);
  ContactManifold one;
  REQUIRE(collide(hb, pose(Vector3d::Zero()), hc, pose({0, 0, 0.5 + reach - 1e-6}, Eigen::Quaterniond(Eigen::AngleAxisd(tilt, Vector3d::UnitX())))
                  , 1e-3, cache, one));
  REQUIRE(one.points.size() == 1);
  CHECK(one.points[0].depth == Approx(1e-6).margin(kExact));
  Vector3d axis;
  CHECK(separation(hb, pose(Vector3d::Zero()), hc, pose({0, 0, 0.5 + reach + 0.01}, Eigen::Quaterniond(Eigen::AngleAxisd(tilt, Vector3d::UnitX()))),
                   cache, axis) == Approx(0.01).margin(kExact));
}

TEST_CASE("a can tilted a little holds the rim within the margin, each point at its own depth",
          "[narrow][revolved]") {
  // Tilted by 0.01 rad about x, its lowest rim point 1e-6 m into the box: a rim point a turn phi
  // from the lowest stands r sin(tilt) (1 - cos phi) higher, within the 1 mm margin up to about
  // 3/4 of a turn for r = 0.1 m. As it rocks, those points come down: each is a contact before it
  // touches, not only the lowest one (which alone is held beyond the margin's reach).
  const double tilt = 0.01, r = 0.1, h = 0.3, margin = 1e-3;
  const ConvexPiece can = makeCylinder(r, h);
  const CollisionHull hb = makeCollisionHull(kBox), hc = makeCollisionHull(can);
  const double reach = r * std::sin(tilt) + h / 2 * std::cos(tilt);
  SatCache cache;
  ContactManifold m;
  const Eigen::Quaterniond tilted(Eigen::AngleAxisd(tilt, Vector3d::UnitX()));
  REQUIRE(collide(hb, pose(Vector3d::Zero()), hc, pose({0, 0, 0.5 + reach - 1e-6}, tilted), margin, cache, m));
  REQUIRE(m.points.size() >= 3);
  CHECK(deepest(m) == Approx(1e-6).margin(kExact));
  const Vector3d centre(0, 0, 0.5 + reach - 1e-6), axis = tilted * Vector3d::UnitZ();
  const Vector3d base = centre - h / 2 * axis;
  for (const ContactPoint& p : m.points) {
    // the base's plane above p: (x - base) . axis = 0; p is a rim point, r from the base's centre
    const double z = base.z() - ((p.position.x() - base.x()) * axis.x() + (p.position.y() - base.y()) * axis.y()) / axis.z();
    CHECK(p.depth == Approx(0.5 - z).margin(kExact));
    CHECK((Vector3d(p.position.x(), p.position.y(), z) - base).norm() == Approx(r).margin(kExact));
    CHECK(p.depth >= -margin);
  }
}

TEST_CASE("a cone stands on its base at its rim, and on its apex at one point", "[narrow][revolved]") {
  const ConvexPiece cone = makeCone(0.1, 0.3);   // base at z = -0.15 in its own frame
  const CollisionHull hb = makeCollisionHull(kBox), hc = makeCollisionHull(cone);
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(hb, pose(Vector3d::Zero()), hc, pose({0, 0, 0.65 - 1e-7}), 1e-3, cache, m));
  CHECK(m.points.size() == 8);
  CHECK(deepest(m) == Approx(1e-7).margin(kExact));
  const Eigen::Quaterniond upside_down(Eigen::AngleAxisd(M_PI, Vector3d::UnitX()));
  ContactManifold tip;
  REQUIRE(collide(hb, pose(Vector3d::Zero()), hc, pose({0.2, 0.1, 0.65 - 1e-7}, upside_down), 1e-3, cache, tip));
  REQUIRE(tip.points.size() == 1);
  CHECK((tip.points[0].position - Vector3d(0.2, 0.1, 0.5)).norm() < 1e-6);
}

TEST_CASE("a ball beside a cylinder's side: the distance between the axis and the centre, less the radii",
          "[narrow][revolved]") {
  const ConvexPiece roller = makeCylinder(0.1, 0.3), ball = makeSphere(0.05);
  const CollisionHull hc = makeCollisionHull(roller), hs = makeCollisionHull(ball);
  for (const double gap : {0.02, 1e-4, -1e-4, -0.01}) {
    SatCache cache;
    Vector3d axis;
    const Eigen::Isometry3d ps = pose({0.15 + gap, 0, 0.05});   // centre 0.15 + gap from the axis
    CHECK(separation(hc, pose(Vector3d::Zero()), hs, ps, cache, axis) == Approx(gap).margin(kExact));
    CHECK((axis - Vector3d::UnitX()).norm() < 1e-6);
  }
}

TEST_CASE("solids of revolution on the ground: a standing can's rim, a lying one's length, a cone's apex",
          "[ground][revolved]") {
  const ConvexPiece can = makeCylinder(0.05, 0.2), cone = makeCone(0.1, 0.3);
  ContactManifold m;
  REQUIRE(collideGround(can, pose({0, 0, 0.1 - 1e-7}), 0, 1e-3, m));
  CHECK(m.points.size() == 8);
  for (const ContactPoint& p : m.points) CHECK(p.depth == Approx(1e-7).margin(kExact));
  REQUIRE(collideGround(can, pose({0, 0, 0.05}, kLying), 0, 1e-3, m));
  CHECK(m.points.size() == 2);
  const double tilt = 0.3;
  const Eigen::Quaterniond tilted(Eigen::AngleAxisd(tilt, Vector3d::UnitY()));
  const double reach = 0.05 * std::sin(tilt) + 0.1 * std::cos(tilt);
  CHECK(groundSeparation(can, pose({0, 0, 1}, tilted), 0) == Approx(1 - reach).margin(kExact));
  REQUIRE(collideGround(can, pose({0, 0, reach - 1e-6}, tilted), 0, 1e-3, m));
  REQUIRE(m.points.size() == 1);
  CHECK(m.points[0].depth == Approx(1e-6).margin(kExact));
  const Eigen::Quaterniond upside_down(Eigen::AngleAxisd(M_PI, Vector3d::UnitX()));
  REQUIRE(collideGround(cone, pose({0, 0, 0.15 - 1e-7}, upside_down), 0, 1e-3, m));
  REQUIRE(m.points.size() == 1);
  CHECK(m.points[0].depth == Approx(1e-7).margin(kExact));
}
