// Hand-worked contact cases: every expected number below follows from the box sizes and poses.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;
using test::rotation;

namespace {

const Eigen::Isometry3d kIdentity = Eigen::Isometry3d::Identity();

// True when each expected xy position matches one contact point (in any order).
bool sameXy(const ContactManifold& m, std::vector<Eigen::Vector2d> expected, double tol) {
  if (m.points.size() != expected.size()) return false;
  for (const ContactPoint& p : m.points) {
    const auto it = std::find_if(expected.begin(), expected.end(), [&](const Eigen::Vector2d& e) {
      return (p.position.head<2>() - e).norm() < tol;
    });
    if (it == expected.end()) return false;
    expected.erase(it);
  }
  return true;
}

void checkSane(const ContactManifold& m) {
  REQUIRE(m.normal.allFinite());
  CHECK(m.normal.norm() == Approx(1).epsilon(1e-12));
  CHECK(!m.points.empty());
  CHECK(m.points.size() <= 8);
  for (const ContactPoint& p : m.points) {
    CHECK(p.position.allFinite());
    CHECK(std::isfinite(p.depth));
  }
}

}  // namespace

TEST_CASE("face-face: box resting on a box, 4 corners, exact depth and normal", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  SatCache cache;
  const auto m = collide(box, kIdentity, box, pose({0, 0, 0.99}), 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(m->normal == Vector3d(0, 0, 1));  // from A (below) to B (above)
  CHECK(sameXy(*m, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, 1e-12));
  for (const ContactPoint& p : m->points) {
    CHECK(p.depth == Approx(0.01).epsilon(1e-12));
    CHECK(p.position.z() == Approx(0.495).epsilon(1e-12));  // midway between 0.49 and 0.5
  }
  SECTION("the same pair the other way round: the normal flips") {
    SatCache other;
    const auto r = collide(box, pose({0, 0, 0.99}), box, kIdentity, 0.0, other);
    REQUIRE(r);
    CHECK(r->normal == Vector3d(0, 0, -1));
    CHECK(r->points.size() == 4);
  }
}

TEST_CASE("face-face clipped: a box overhanging a bigger box", "[narrow]") {
  const ConvexPiece big = makeBox(Vector3d(1, 1, 0.5)), small = makeBox(Vector3d(0.5, 0.5, 0.5));
  SatCache cache;
  // small's footprint x in [0.3, 1.3], y in [0.1, 1.1]; big's top ends at x = 1, y = 1
  const auto m = collide(big, kIdentity, small, pose({0.8, 0.6, 0.98}), 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(m->normal.isApprox(Vector3d(0, 0, 1), 1e-15));
  CHECK(sameXy(*m, {{0.3, 0.1}, {1, 0.1}, {1, 1}, {0.3, 1}}, 1e-12));
  for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(0.02).epsilon(1e-12));
}

TEST_CASE("edge-edge: two boxes crossed at their edges give one point", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const double r2 = std::sqrt(2.0), d = 0.01;
  // A's top edge runs along x at z = sqrt2/2; B's bottom edge along y at z_B - sqrt2/2
  const auto pa = pose({0, 0, 0}, rotation(std::numbers::pi / 4, Vector3d::UnitX()));
  const auto pb = pose({0, 0, r2 - d}, rotation(std::numbers::pi / 4, Vector3d::UnitY()));
  SatCache cache;
  const auto m = collide(box, pa, box, pb, 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  REQUIRE(m->points.size() == 1);
  CHECK(cache.axis == SatCache::Axis::Edges);
  CHECK(m->normal.isApprox(Vector3d(0, 0, 1), 1e-12));  // x cross y, from A to B
  CHECK(m->points[0].depth == Approx(d).epsilon(1e-9));
  CHECK(m->points[0].position.isApprox(Vector3d(0, 0, r2 / 2 - d / 2), 1e-12));
}

TEST_CASE("vertex-face: a box balanced on its corner gives one point", "[narrow]") {
  const ConvexPiece ground = makeBox(Vector3d(2, 2, 0.5)), cube = makeBox(Vector3d(0.5, 0.5, 0.5));
  const auto corner_down = Eigen::Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d(0, 0, 1));
  const double d = 0.003, h = 0.5 * std::sqrt(3.0);
  SatCache cache;
  const auto m = collide(ground, kIdentity, cube, pose({0, 0, 0.5 + h - d}, corner_down), 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  REQUIRE(m->points.size() == 1);
  CHECK(m->normal.isApprox(Vector3d(0, 0, 1), 1e-15));
  CHECK(m->points[0].depth == Approx(d).epsilon(1e-9));
  CHECK(m->points[0].position.isApprox(Vector3d(0, 0, 0.5 - d / 2), 1e-12));
}

TEST_CASE("touching and barely separated boxes against the margin", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  SatCache cache;
  SECTION("touching: depth 0 is a contact even with margin 0") {
    const auto m = collide(box, kIdentity, box, pose({0.2, 0.1, 1.0}), 0.0, cache);
    REQUIRE(m);
    CHECK(m->points.size() == 4);
    for (const ContactPoint& p : m->points) CHECK(std::abs(p.depth) < 1e-15);
  }
  SECTION("separated by 1e-9: reported within a margin, with negative depth") {
    const auto m = collide(box, kIdentity, box, pose({0, 0, 1 + 1e-9}), 1e-6, cache);
    REQUIRE(m);
    CHECK(m->points.size() == 4);
    for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(-1e-9).epsilon(1e-6));
  }
  SECTION("separated by 1e-9: nothing with margin 0") {
    CHECK_FALSE(collide(box, kIdentity, box, pose({0, 0, 1 + 1e-9}), 0.0, cache));
  }
}

TEST_CASE("coincident boxes: no NaN, a valid face axis", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.3, 0.2));
  SatCache cache;
  const auto m = collide(box, pose({1, 2, 3}), box, pose({1, 2, 3}), 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(cache.axis != SatCache::Axis::None);
  for (const ContactPoint& p : m->points) CHECK(p.depth > 0.39);  // the thinnest axis: 2 * 0.2
}

TEST_CASE("a thin plate (1 m x 1 m x 1 mm) resting on a box", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5)), plate = makeBox(Vector3d(0.5, 0.5, 5e-4));
  const double d = 1e-4;
  const double turn = GENERATE(0.0, 0.5);  // 0.5 rad about z: the overlap is an octagon
  SatCache cache;
  const auto m = collide(box, kIdentity, plate,
                         pose({0, 0, 0.5 + 5e-4 - d}, rotation(turn, Vector3d::UnitZ())), 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(m->normal.isApprox(Vector3d(0, 0, 1), 1e-15));
  // aligned, the overlap is the plate's square; turned, an octagon whose largest quadrilateral
  // loses 24 % of it: all eight corners are kept
  const std::size_t corners = turn == 0.0 ? 4 : 8;
  CHECK(m->points.size() == corners);
  for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(d).epsilon(1e-9));
  SECTION("plate as A: the normal points down, to the box") {
    SatCache other;
    const auto r = collide(plate, pose({0, 0, 0.5 + 5e-4 - d}, rotation(turn, Vector3d::UnitZ())),
                           box, kIdentity, 0.0, other);
    REQUIRE(r);
    CHECK(r->normal.isApprox(Vector3d(0, 0, -1), 1e-15));
    CHECK(r->points.size() == corners);
  }
}

TEST_CASE("nearly parallel edges (1e-9 rad): no NaN, a face contact along the ridge", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const double r2 = std::sqrt(2.0), d = 0.01;
  const auto ridge = rotation(std::numbers::pi / 4, Vector3d::UnitX());
  const auto pa = pose({0, 0, 0}, ridge);
  const auto pb = pose({0, 0, r2 - d}, rotation(1e-9, Vector3d::UnitZ()) * ridge);
  SatCache cache;
  const auto m = collide(box, pa, box, pb, 0.0, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(cache.axis != SatCache::Axis::Edges);
  // ridge on ridge: leaving along a face normal of A takes d / sqrt2, less than d straight up
  CHECK(m->normal.z() == Approx(1 / r2).epsilon(1e-6));
  for (const ContactPoint& p : m->points) {
    CHECK(p.depth == Approx(d / r2).epsilon(1e-6));
    CHECK(std::abs(p.position.y()) < 0.01);
  }
}

TEST_CASE("SatCache: a separated pair exits on the cached axis", "[narrow][cache]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const CollisionHull hull = makeCollisionHull(box);
  SatCache cache;
  ContactManifold m;
  CHECK_FALSE(collide(hull, kIdentity, hull, pose({1.1, 0.2, 0}), 0.01, cache, m));
  CHECK(cache.last_use == SatCache::Use::Miss);
  CHECK(cache.axis == SatCache::Axis::FaceA);
  CHECK_FALSE(collide(hull, kIdentity, hull, pose({1.1, 0.2, 0}), 0.01, cache, m));
  CHECK(cache.last_use == SatCache::Use::EarlyExit);
  CHECK(cache.early_exits == 1);
}

TEST_CASE("SatCache: a resting pair reuses the cached face and repeats its manifold",
          "[narrow][cache]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const CollisionHull hull = makeCollisionHull(box);
  const auto pb = pose({0.1, 0, 0.995}, rotation(0.01, Vector3d(1, 2, 3)));
  SatCache cache;
  ContactManifold first, second;
  REQUIRE(collide(hull, kIdentity, hull, pb, 0.01, cache, first));
  REQUIRE(collide(hull, kIdentity, hull, pb, 0.01, cache, second));
  CHECK(cache.last_use == SatCache::Use::Reused);
  CHECK(first.normal == second.normal);
  REQUIRE(first.points.size() == second.points.size());
  for (size_t i = 0; i < first.points.size(); ++i) {
    CHECK(first.points[i].position == second.points[i].position);
    CHECK(first.points[i].depth == second.points[i].depth);
    CHECK(first.points[i].feature == second.points[i].feature);
  }
}

TEST_CASE("a box resting flat stays face-face under small tilts", "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const auto q = rotation(1e-4 * std::abs(u(rng)), Vector3d(u(rng), u(rng), u(rng))) *
                   rotation(u(rng), Vector3d::UnitZ());
    SatCache cache;
    const auto m = collide(box, kIdentity, box, pose({0.3 * u(rng), 0.3 * u(rng), 0.999}, q), 0.0,
                           cache);
    REQUIRE(m);
    CHECK(cache.axis != SatCache::Axis::Edges);
    CHECK(m->points.size() >= 3);
    CHECK(m->normal.z() > 0.999);
  }
}

// Two cards of a tent (0.5 x 64 x 89 mm, leaning 25 degrees each way) whose top inner edges meet,
// parallel, 0.01 mm apart. Every direction between the two inner faces' normals separates them;
// the contact's normal is the bisector, horizontal, and the pair's gap along it is the 0.01 mm
// (the faces' own normals, 25 degrees off, see only 0.01 cos 25 mm and would push one card up and
// the other down).
TEST_CASE("parallel edges meeting (a tent's ridge): the normal bisects the two faces' normals", "[narrow]") {
  const double t = 0.5e-3, l = 89e-3, lean = 25 * std::numbers::pi / 180, gap = 1e-5;
  const ConvexPiece card = makeBox(Vector3d(t / 2, 32e-3, l / 2));
  const double dx = t / 2 * std::cos(lean) + l / 2 * std::sin(lean) + gap / 2;
  const auto left = pose({-dx, 0, l / 2}, rotation(lean, Vector3d::UnitY()));
  const auto right = pose({dx, 0, l / 2}, rotation(-lean, Vector3d::UnitY()));
  SatCache cache;
  const auto m = collide(card, left, card, right, 1e-4, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(m->normal.isApprox(Vector3d(1, 0, 0), 1e-12));   // from A (left) to B (right)
  double deepest = -INFINITY;
  for (const ContactPoint& p : m->points) deepest = std::max(deepest, p.depth);
  CHECK(deepest == Approx(-gap).epsilon(1e-6));
  SECTION("the pair the other way round: the normal flips") {
    SatCache other;
    const auto r = collide(card, right, card, left, 1e-4, other);
    REQUIRE(r);
    CHECK(r->normal.isApprox(Vector3d(-1, 0, 0), 1e-12));
  }
}

// The same ridge, apart, touching and overlapping, and twisted by 1e-4 rad: the two edges touch
// along their whole 64 mm, so the contact holds them at both ends, one point at y = -32 mm and one at
// +32 mm, each with its own depth along the normal. Clipping the end face of one card against the
// other's inner face put the points where rounding cut the edge (one end only, or 2 mm and 24 mm
// from it), and a ridge held at one end turned the tent about it; the closest points of a pair
// apart gave one point only.
TEST_CASE("parallel edges meeting (a tent's ridge): a contact point at each end of the ridge", "[narrow]") {
  const double t = 0.5e-3, l = 89e-3, lean = 25 * std::numbers::pi / 180, half_width = 32e-3;
  const ConvexPiece card = makeBox(Vector3d(t / 2, half_width, l / 2));
  for (const double gap : {1e-5, 1e-7, 0.0, -1e-7}) {
    for (const double twist : {0.0, 1e-4}) {
      CAPTURE(gap, twist);
      const double dx = t / 2 * std::cos(lean) + l / 2 * std::sin(lean) + gap / 2;
      const auto left = pose({-dx, 0, l / 2}, rotation(lean, Vector3d::UnitY()));
      const auto right = pose({dx, 0, l / 2}, rotation(twist, Vector3d::UnitX()) * rotation(-lean, Vector3d::UnitY()));
      SatCache cache;
      const auto m = collide(card, left, card, right, 1e-4, cache);
      REQUIRE(m);
      checkSane(*m);
      REQUIRE(m->points.size() == 2);
      const double y0 = m->points[0].position.y(), y1 = m->points[1].position.y();
      CHECK(std::min(y0, y1) == Approx(-half_width).margin(1e-5));
      CHECK(std::max(y0, y1) == Approx(half_width).margin(1e-5));
      CHECK(m->normal.x() > 1 - 1e-6);   // horizontal, from the left card to the right one
      // the twist turns the right card's edge about the ridge's middle: its ends rise and fall by
      // 1e-4 * the ridge's lever (the top lies l/2 above the card's centre), along the normal by
      // sin(lean) of that; untwisted both ends are the gap apart
      const double spread = twist * (l / 2) * std::sin(lean) * half_width / (l / 2) + 1e-9;
      for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(-gap).margin(2 * spread + 1e-9));
    }
  }
}

// A 1 m cube tilted by 1e-6 rad under a level 10 m cube resting on it: the small top face's edges
// touch the large bottom face's inside, so the contact's normal is the large face's, exactly
// vertical (the small face's, tilted 1e-6 rad, turned a heavy cube's weight into a sideways push).
TEST_CASE("face on face, one face larger: the normal is the larger face's", "[narrow]") {
  const ConvexPiece small = makeBox(Vector3d(0.5, 0.5, 0.5)), big = makeBox(Vector3d(5, 5, 5));
  const auto tilted = pose({0, 0, 0.5}, rotation(1e-6, Vector3d::UnitY()));
  const auto level = pose({0, 0, 1 + 5 - 1e-7});
  SatCache cache;
  const auto m = collide(small, tilted, big, level, 1e-4, cache);   // the small cube is A
  REQUIRE(m);
  checkSane(*m);
  CHECK(m->normal.isApprox(Vector3d(0, 0, 1), 1e-15));
  SECTION("the pair the other way round: the same face, the normal flips") {
    SatCache other;
    const auto r = collide(big, level, small, tilted, 1e-4, other);
    REQUIRE(r);
    CHECK(r->normal.isApprox(Vector3d(0, 0, -1), 1e-15));
  }
}

// Two 0.4 m cubes of a settling pile (their poses as the time-stepping pile had them): the upper
// one's bottom edge level with the lower one's top edge beside it, 0.70 mm apart across. The
// reference face (the lower cube's side) and the upper cube's side face meet only along the line
// of that edge, which the clip dropped: the pair, within the 1 mm margin, was reported as nothing
// at this step and found at the next, and a kept manifold held the "nothing".
TEST_CASE("two cubes apart within the margin, meeting only along a face's border line: a contact at their distance",
          "[narrow]") {
  const ConvexPiece box = makeBox(Vector3d(0.2, 0.2, 0.2));
  Eigen::Isometry3d upper = Eigen::Isometry3d::Identity(), lower = Eigen::Isometry3d::Identity();
  upper.linear() = Eigen::Quaterniond(1.4314459461412145e-07, -0.22565271107398063, 0.97420780841754118,
                                      -1.7982282713727459e-06).normalized().toRotationMatrix();
  upper.translation() = Vector3d(-0.027212819998370576, 1.841350110966355, 0.5999992563594555);
  lower.linear() = Eigen::Quaterniond(-0.33956734987741521, -0.62023706346624352, -0.3395673498774151,
                                      0.62023706346624397).normalized().toRotationMatrix();
  lower.translation() = Vector3d(-0.39194170207399964, 1.5101567950109067, 0.20000000000000018);
  const CollisionHull hull = makeCollisionHull(box);
  const double distance = pieceDistance(hull, upper, hull, lower).distance;
  REQUIRE(distance == Approx(7.046e-4).margin(1e-7));
  SatCache cache;
  const auto m = collide(box, upper, box, lower, 1e-3, cache);
  REQUIRE(m);
  checkSane(*m);
  CHECK(std::abs(m->normal.z()) < 1e-3);   // across, not down
  for (const ContactPoint& p : m->points) CHECK(p.depth == Approx(-distance).margin(1e-9));
}
