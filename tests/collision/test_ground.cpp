#include <catch2/catch.hpp>

#include <cmath>

#include "collision/narrow_internal.h"
#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;
using test::rotation;

namespace {

// Twice the area of the convex polygon through the points, taken in angular order about their mean.
double supportArea(const ContactManifold& m) {
  Vector3d c = Vector3d::Zero();
  for (const ContactPoint& p : m.points) c += p.position;
  c /= double(m.points.size());
  std::vector<Vector3d> ring;
  for (const ContactPoint& p : m.points) ring.push_back(p.position - c);
  std::sort(ring.begin(), ring.end(), [](const Vector3d& a, const Vector3d& b) {
    return std::atan2(a.y(), a.x()) < std::atan2(b.y(), b.x());
  });
  double area2 = 0;
  for (size_t i = 0; i < ring.size(); ++i) area2 += ring[i].cross(ring[(i + 1) % ring.size()]).z();
  return area2;
}

}  // namespace

TEST_CASE("ground: a flat box gives its 4 bottom corners", "[ground]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.3, 0.2));
  const auto m = collideGround(box, pose({1, 2, 0.2 + 0.1 - 0.004}), 0.1, 0.0);
  REQUIRE(m);
  CHECK(m->normal == Vector3d(0, 0, -1));  // from the piece (A) to the ground (B)
  REQUIRE(m->points.size() == 4);
  for (const ContactPoint& p : m->points) {
    CHECK(p.depth == Approx(0.004).epsilon(1e-9));
    CHECK(p.position.z() == Approx(0.1 - 0.002).epsilon(1e-12));
  }
  CHECK(supportArea(*m) == Approx(2 * 1.0 * 0.6).epsilon(1e-12));
}

TEST_CASE("ground: a tilted box touches with an edge (2 points) or a corner (1)", "[ground]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  SECTION("edge: tilted about y") {
    const auto x = pose({0, 0, 0}, rotation(0.2, Vector3d::UnitY()));
    const double lift = -groundSeparation(box, x, 0.0) - 1e-3;  // 1 mm into the ground
    const auto m = collideGround(box, pose({0, 0, lift}, rotation(0.2, Vector3d::UnitY())), 0.0, 0.0);
    REQUIRE(m);
    CHECK(m->points.size() == 2);
    for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(1e-3).epsilon(1e-9));
  }
  SECTION("corner: tilted about a diagonal") {
    const auto q = rotation(0.3, Vector3d(1, 1, 0));
    const double lift = -groundSeparation(box, pose({0, 0, 0}, q), 0.0) - 1e-3;
    const auto m = collideGround(box, pose({0, 0, lift}, q), 0.0, 0.0);
    REQUIRE(m);
    CHECK(m->points.size() == 1);
  }
}

TEST_CASE("ground: 8 coplanar points, duplicated, reduce to the 4 corners", "[ground]") {
  ConvexPiece piece;  // only vertices matter to the ground test
  for (int copy = 0; copy < 2; ++copy) {
    for (double x : {-1.0, 1.0}) {
      for (double y : {-1.0, 1.0}) piece.vertices.emplace_back(x, y, 0.0);
    }
  }
  piece.vertices.emplace_back(0, 0, 1);
  const auto m = collideGround(piece, Eigen::Isometry3d::Identity(), 0.0, 1e-6);
  REQUIRE(m);
  REQUIRE(m->points.size() == 4);
  CHECK(supportArea(*m) == Approx(2 * 4.0).epsilon(1e-12));
}

TEST_CASE("ground: an octagon keeps its eight corners, where four would lose 29 % of its area", "[ground]") {
  ConvexPiece piece;
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4 + 0.1;
    piece.vertices.emplace_back(std::cos(a), std::sin(a), k % 2 ? 1e-4 : 0.0);  // slightly uneven
  }
  const auto m = collideGround(piece, Eigen::Isometry3d::Identity(), 1e-3, 0.0);
  REQUIRE(m);
  REQUIRE(m->points.size() == 8);
  const double octagon2 = 2 * 2 * std::sqrt(2.0);  // twice the area of a unit-radius octagon
  CHECK(supportArea(*m) == Approx(octagon2).epsilon(1e-12));  // all of it
}

TEST_CASE("groundSeparation: lowest vertex height above the plane", "[ground]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const auto q = Eigen::Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d(0, 0, 1));
  CHECK(groundSeparation(box, pose({0, 0, 2}, q), 0.5) ==
        Approx(2 - 0.5 * std::sqrt(3.0) - 0.5).epsilon(1e-12));
}

// Found by the sanitizer build: a body whose pose went NaN (a fault the fault check reports after
// the step) reached the four-point reduction with NaN positions, where every area comparison is
// false and a point index stayed -1 (read before the vector). It must keep four points, not crash.
TEST_CASE("contact reduction keeps four points of a manifold whose positions are NaN", "[collision][ground]") {
  std::vector<ContactPoint> points(6);
  for (ContactPoint& p : points) p.position = Eigen::Vector3d::Constant(std::nan(""));
  narrow::reduceManifold(points, Eigen::Vector3d::UnitZ());
  CHECK(points.size() <= 4);
}

// A square with its corners cut by c (an octagon, as two squares turned against each other clip
// to). Cut by 2 % (faces turned a degree or so) the best quadrilateral of its corners holds 98 %
// of it, and four points are kept; cut by 40 %, it holds 74 %: all eight are kept.
TEST_CASE("contact reduction keeps corners beyond four only where each adds 5 % of the support", "[collision][ground]") {
  for (const double c : {0.02, 0.4}) {
    std::vector<ContactPoint> points;
    for (int k = 0; k < 4; ++k) {   // the square [-1, 1]^2 turned by k quarter turns
      const Eigen::Rotation2Dd turn(k * std::numbers::pi / 2);
      for (const Eigen::Vector2d& corner : {Eigen::Vector2d(1, -(1 - c)), Eigen::Vector2d(1 - c, -1)}) {
        const Eigen::Vector2d q = turn * corner;
        points.push_back({Vector3d(q.x(), q.y(), 0), 1e-4, std::uint32_t(points.size())});
      }
    }
    std::vector<ContactPoint> kept = points;
    narrow::reduceManifold(kept, Vector3d::UnitZ());
    ContactManifold m;
    m.points = kept;
    const double whole = 2 * (4 - 2 * c * c);   // twice the octagon's area
    if (c < 0.1) {
      CHECK(kept.size() == 4);
      CHECK(supportArea(m) >= 0.98 * whole);
    } else {
      CHECK(kept.size() == 8);
      CHECK(supportArea(m) == Approx(whole).epsilon(1e-12));
    }
  }
}
