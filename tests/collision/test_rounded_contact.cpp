// Rounded pieces (exact spheres, capsules; collision/rounded_contact.cpp) against closed forms:
// distances and depths of sphere pairs, a sphere against a box (the distance from a point to a
// box), capsules lying on a box and beside each other (two points, the support's width), and the
// ground. Tolerance 1e-9 m: every answer here is a closed form evaluated in double precision on
// sizes of order 1 m, so anything above rounding (1e-15 relative) by far is an error.
#include <catch2/catch.hpp>

#include <random>

#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;

namespace {

constexpr double kExact = 1e-9;   // m

// Distance from point p to the axis-aligned box of half extents h centred at the origin, or minus
// the depth of p inside it.
double signedBoxDistance(const Vector3d& p, const Vector3d& h) {
  const Vector3d q = p.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

double deepest(const ContactManifold& m) {
  double d = -INFINITY;
  for (const ContactPoint& p : m.points) d = std::max(d, p.depth);
  return d;
}

}  // namespace

TEST_CASE("sphere pairs: depth, normal and separation are the closed forms", "[narrow][rounded]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 1);
  for (int i = 0; i < 200; ++i) {
    const double ra = size(rng), rb = size(rng);
    const ConvexPiece a = makeSphere(ra), b = makeSphere(rb);
    const CollisionHull ha = makeCollisionHull(a), hb = makeCollisionHull(b);
    const Vector3d ca(u(rng), u(rng), u(rng)), cb(u(rng), u(rng), u(rng));
    const Eigen::Quaterniond qa = Eigen::Quaterniond::UnitRandom(), qb = Eigen::Quaterniond::UnitRandom();
    const double gap = (cb - ca).norm() - ra - rb;
    SatCache cache;
    Vector3d axis;
    CHECK(separation(ha, pose(ca, qa), hb, pose(cb, qb), cache, axis) == Approx(gap).margin(kExact));
    ContactManifold m;
    const bool touching = collide(ha, pose(ca, qa), hb, pose(cb, qb), 0.01, cache, m);
    REQUIRE(touching == (gap <= 0.01));
    if (!touching) continue;
    REQUIRE(m.points.size() == 1);
    CHECK(m.points[0].depth == Approx(-gap).margin(kExact));
    CHECK((m.normal - (cb - ca).normalized()).norm() < kExact);
    // midway between the surfaces, on the line of centres
    const Vector3d mid = 0.5 * ((ca + ra * m.normal) + (cb - rb * m.normal));
    CHECK((m.points[0].position - mid).norm() < kExact);
    if (gap > 0) {
      const PieceDistance d = pieceDistance(ha, pose(ca, qa), hb, pose(cb, qb));
      CHECK(d.distance == Approx(gap).margin(kExact));
      CHECK((d.point_a - (ca + ra * m.normal)).norm() < kExact);
    }
  }
}

TEST_CASE("a sphere against a box: the distance from its centre to the box, less the radius", "[narrow][rounded]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  const Vector3d h(0.5, 0.3, 0.2);
  const ConvexPiece box = makeBox(h), ball = makeSphere(0.25);
  const CollisionHull hbox = makeCollisionHull(box), hball = makeCollisionHull(ball);
  int touching = 0;
  for (int i = 0; i < 500; ++i) {
    const Vector3d c(u(rng), u(rng), u(rng));
    const double expected = signedBoxDistance(c, h) - 0.25;
    SatCache cache;
    CHECK(separation(hbox, pose(Vector3d::Zero()), hball, pose(c), cache) == Approx(expected).margin(kExact));
    ContactManifold m;
    if (!collide(hbox, pose(Vector3d::Zero()), hball, pose(c), 0.0, cache, m)) {
      CHECK(expected > 0);
      continue;
    }
    ++touching;
    CHECK(deepest(m) == Approx(-expected).margin(kExact));
    // the normal points from the box to the ball: along it the ball's centre lies outside the box
    CHECK(m.normal.dot(c) > 0);
  }
  CHECK(touching > 50);
}

TEST_CASE("a capsule lying on a box touches along its length: two points, equally deep", "[narrow][rounded]") {
  const ConvexPiece box = makeBox({1, 1, 0.5}), capsule = makeCapsule(0.1, 0.8);
  const CollisionHull hbox = makeCollisionHull(box), hcap = makeCollisionHull(capsule);
  // lying along x on the top face (z = 0.5), 1 micrometre deep
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()));
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(hbox, pose(Vector3d::Zero()), hcap, pose({0.2, 0, 0.6 - 1e-6}, lying), 1e-3, cache, m));
  REQUIRE(m.points.size() == 2);
  CHECK((m.normal - Vector3d::UnitZ()).norm() < kExact);
  for (const ContactPoint& p : m.points) CHECK(p.depth == Approx(1e-6).margin(kExact));
  CHECK(std::abs(m.points[0].position.x() - m.points[1].position.x()) == Approx(0.8).margin(kExact));
  CHECK_FALSE(m.closest_points);   // the box's face holds the normal
  SECTION("hanging over the edge: the support ends at the edge") {
    ContactManifold over;
    REQUIRE(collide(hbox, pose(Vector3d::Zero()), hcap, pose({0.9, 0, 0.6}, lying), 1e-3, cache, over));
    REQUIRE(over.points.size() == 2);
    const double hi = std::max(over.points[0].position.x(), over.points[1].position.x());
    const double lo = std::min(over.points[0].position.x(), over.points[1].position.x());
    CHECK(hi == Approx(1.0).margin(kExact));
    CHECK(lo == Approx(0.5).margin(kExact));
  }
  SECTION("tilted: the lower end alone") {
    const Eigen::Quaterniond tilted = Eigen::AngleAxisd(0.01, Vector3d::UnitY()) * lying;
    ContactManifold one;
    REQUIRE(collide(hbox, pose(Vector3d::Zero()), hcap, pose({0, 0, 0.6 + 0.4 * std::sin(0.01)}, tilted), 1e-3, cache, one));
    CHECK(one.points.size() == 1);
  }
}

TEST_CASE("parallel capsules side by side touch along their overlap", "[narrow][rounded]") {
  const ConvexPiece a = makeCapsule(0.1, 1.0), b = makeCapsule(0.15, 0.6);
  const CollisionHull ha = makeCollisionHull(a), hb = makeCollisionHull(b);
  SatCache cache;
  ContactManifold m;
  // b beside a along y, shifted along the axis so that it overhangs a's end by 0.1
  REQUIRE(collide(ha, pose(Vector3d::Zero()), hb, pose({0, 0.25 - 2e-6, 0.3}), 1e-3, cache, m));
  REQUIRE(m.points.size() == 2);
  CHECK((m.normal - Vector3d::UnitY()).norm() < kExact);
  for (const ContactPoint& p : m.points) CHECK(p.depth == Approx(2e-6).margin(kExact));
  const double z0 = std::min(m.points[0].position.z(), m.points[1].position.z());
  const double z1 = std::max(m.points[0].position.z(), m.points[1].position.z());
  CHECK(z0 == Approx(0.0).margin(kExact));
  CHECK(z1 == Approx(0.5).margin(kExact));
}

TEST_CASE("crossed capsules touch at one point, at the distance between their axes", "[narrow][rounded]") {
  const ConvexPiece a = makeCapsule(0.1, 1.0);
  const CollisionHull h = makeCollisionHull(a);
  const Eigen::Quaterniond along_x(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()));
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(h, pose(Vector3d::Zero()), h, pose({0.1, 0.1999, 0.2}, along_x), 1e-3, cache, m));
  REQUIRE(m.points.size() == 1);
  CHECK(m.points[0].depth == Approx(1e-4).margin(kExact));
  CHECK((m.normal - Vector3d::UnitY()).norm() < kExact);
}

TEST_CASE("overlapping cores still part along the least overlap", "[narrow][rounded]") {
  // a ball whose centre is inside a box: pushed out through the nearest face
  const ConvexPiece box = makeBox({1, 1, 1}), ball = makeSphere(0.1);
  const CollisionHull hbox = makeCollisionHull(box), hball = makeCollisionHull(ball);
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(hbox, pose(Vector3d::Zero()), hball, pose({0.2, 0.1, 0.9}), 0.0, cache, m));
  CHECK((m.normal - Vector3d::UnitZ()).norm() < kExact);
  CHECK(deepest(m) == Approx(0.2).margin(kExact));
  // two balls with the same centre: some unit normal, depth the sum of the radii
  ContactManifold same;
  REQUIRE(collide(hball, pose(Vector3d::Zero()), hball, pose(Vector3d::Zero()), 0.0, cache, same));
  CHECK(same.normal.norm() == Approx(1.0));
  CHECK(deepest(same) == Approx(0.2).margin(kExact));
}

TEST_CASE("rounded pieces on the ground: a ball at one point, a lying capsule at both ends", "[ground][rounded]") {
  const ConvexPiece ball = makeSphere(0.3), capsule = makeCapsule(0.1, 2.0);
  ContactManifold m;
  REQUIRE(collideGround(ball, pose({1, 2, 0.3 - 1e-7}), 0, 1e-3, m));
  REQUIRE(m.points.size() == 1);
  CHECK(m.points[0].depth == Approx(1e-7).margin(kExact));
  CHECK((m.points[0].position - Vector3d(1, 2, -0.5e-7)).norm() < kExact);
  CHECK(groundSeparation(ball, pose({0, 0, 1}), 0.5) == Approx(0.2).margin(kExact));
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()));
  REQUIRE(collideGround(capsule, pose({0, 0, 0.1}, lying), 0, 1e-3, m));
  CHECK(m.points.size() == 2);
}
