// supportQuery (GJK, EPA and the polish, collision/support_query.cpp) on sets given only by support
// mappings, against closed forms (spheres, cylinders and cones on a box's face and against a
// sphere, a point in a box) and against the polyhedron oracles of the narrow phase: separation()
// is minus the penetration depth of overlapping polyhedra (SAT over the faces of the Minkowski
// difference), pieceDistance() the distance of separated ones (GJK on vertex lists).
//
// Tolerances. Queries pass 1e-12 m, 1e-12 x sizes of order 1 m, as callers will. Every answer is
// then checked to 1e-9 m (lengths) or 1e-9 (normals, unitless): far above the rounding of the
// closed forms and oracles (1e-15 relative) and far below any contact tolerance, so anything
// above it is an error. Where a normal is not unique (two faces equally deep) the test checks
// instead that moving B by depth x normal leaves the sets just touching.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "collision/narrow_phase.h"
#include "collision/support_query.h"
#include "collision_checks.h"
#include "geometry/convex_hull.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 1e-12;   // m: what the queries are asked for
constexpr double kExact = 1e-9;        // m, and unitless for normals: what is checked

// ---- support mappings ----

SupportMapping sphere(const Vector3d& c, double r) {
  return [=](const Vector3d& d) -> Vector3d { return c + r * d.normalized(); };
}

// A polytope by its vertices: the first vertex farthest along d.
SupportMapping polytope(std::vector<Vector3d> pts) {
  return [pts = std::move(pts)](const Vector3d& d) -> Vector3d {
    std::size_t best = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
      if (pts[i].dot(d) > pts[best].dot(d)) best = i;
    return pts[best];
  };
}

std::vector<Vector3d> worldVertices(const ConvexPiece& piece, const Eigen::Isometry3d& x) {
  std::vector<Vector3d> v;
  for (const Vector3d& p : piece.vertices) v.push_back(x * p);
  return v;
}

// The part of d across the unit axis u, unit; zero when d lies along u (any point of a rim is then
// farthest, and the centre of the disc is one of the farthest points of it). Removing the part
// along u twice: once leaves the rounding of d.u (1e-16 |d|), which the division by a short perp
// would magnify into a rim point off its cap's plane (by 4e-7 m for |perp| ~ 1e-10 |d|).
Vector3d across(const Vector3d& d, const Vector3d& u) {
  Vector3d perp = d - d.dot(u) * u;
  perp -= perp.dot(u) * u;
  const double len = perp.norm();
  return len > 1e-12 * d.norm() ? Vector3d(perp / len) : Vector3d::Zero();
}

// Centre c, unit axis u, radius R, half height h.
SupportMapping cylinder(const Vector3d& c, const Vector3d& u, double R, double h) {
  return [=](const Vector3d& d) -> Vector3d { return c + (d.dot(u) >= 0 ? h : -h) * u + R * across(d, u); };
}

// The centre of its base disc, its apex, the base's radius.
SupportMapping cone(const Vector3d& base, const Vector3d& apex, double R) {
  const Vector3d u = (apex - base).normalized();
  return [=](const Vector3d& d) -> Vector3d {
    const Vector3d rim = base + R * across(d, u);
    return apex.dot(d) >= rim.dot(d) ? apex : rim;
  };
}

// A disc of no height: centre c, unit normal n, radius R.
SupportMapping disc(const Vector3d& c, const Vector3d& n, double R) {
  return [=](const Vector3d& d) -> Vector3d { return c + R * across(d, n); };
}

SupportMapping segment(const Vector3d& p, const Vector3d& q) { return polytope({p, q}); }
SupportMapping point(const Vector3d& p) {
  return [=](const Vector3d&) -> Vector3d { return p; };
}

// Counts the support evaluations of a mapping (each iteration of GJK or EPA evaluates A and B once).
SupportMapping counted(SupportMapping f, long& calls) {
  return [f = std::move(f), &calls](const Vector3d& d) -> Vector3d {
    ++calls;
    return f(d);
  };
}

// ---- checks every answer must pass ----

// Finite, a unit normal, lengths of the right signs, and the points where the header says:
// point_a on A's supporting plane along +normal, point_b on B's along -normal, and their
// difference the distance (apart) or the depth (overlapping) along the normal.
void checkConsistent(const SupportQuery& q, const SupportMapping& a, const SupportMapping& b) {
  REQUIRE(q.normal.allFinite());
  REQUIRE(q.point_a.allFinite());
  REQUIRE(q.point_b.allFinite());
  REQUIRE(std::isfinite(q.distance));
  REQUIRE(std::isfinite(q.depth));
  CHECK(std::abs(q.normal.norm() - 1) < 1e-12);
  CHECK(q.distance >= 0);
  CHECK(q.depth >= 0);
  if (q.overlapping) {
    CHECK(q.distance == 0);
    CHECK((q.point_a - q.point_b - q.depth * q.normal).norm() < kExact);
  } else {
    CHECK(q.depth == 0);
    CHECK((q.point_b - q.point_a - q.distance * q.normal).norm() < kExact);
  }
  CHECK(std::abs(q.normal.dot(a(q.normal) - q.point_a)) < kExact);
  CHECK(std::abs(q.normal.dot(b(-q.normal) - q.point_b)) < kExact);
}

SupportQuery query(const SupportMapping& a, const SupportMapping& b, const Vector3d& ca, const Vector3d& cb) {
  const SupportQuery q = supportQuery(a, b, ca, cb, kTolerance);
  checkConsistent(q, a, b);
  return q;
}

// The signed gap (distance, or minus the depth) of an answer.
double gapOf(const SupportQuery& q) { return q.overlapping ? -q.depth : q.distance; }

Vector3d randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Vector3d(n(rng), n(rng), n(rng)).normalized();
}

Eigen::Quaterniond randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// A point of the ball of radius r about c.
Vector3d insideBall(std::mt19937& rng, const Vector3d& c, double r) {
  std::uniform_real_distribution<double> u(0, 1);
  return c + r * std::cbrt(u(rng)) * randomUnit(rng);
}

// Compares a query on polyhedra with the narrow phase's oracles: overlapping, the SAT depth (and B
// moved by depth x normal just touches A: the normal parts them, unique or not); apart, the
// distance of pieceDistance (GJK on the vertex lists). Tallies the pair, and returns the error.
struct OracleTally {
  int apart = 0, overlapping = 0;
  double worst = 0;
};
void compareWithOracles(const SupportQuery& q, const CollisionHull& ha, const Eigen::Isometry3d& xa,
                        const CollisionHull& hb, const Eigen::Isometry3d& xb, OracleTally& tally) {
  SatCache cache;
  const double sat = separation(ha, xa, hb, xb, cache);
  INFO("sat " << sat);
  if (sat < 0) {
    REQUIRE(q.overlapping);
    ++tally.overlapping;
    CHECK(q.depth == Approx(-sat).margin(kExact));
    tally.worst = std::max(tally.worst, std::abs(q.depth + sat));
    SatCache moved;
    const auto xb_moved = pose(xb.translation() + q.depth * q.normal, Eigen::Quaterniond(xb.linear()));
    CHECK(std::abs(separation(ha, xa, hb, xb_moved, moved)) < kExact);
    return;
  }
  const PieceDistance d = pieceDistance(ha, xa, hb, xb);
  CHECK(gapOf(q) == Approx(d.distance).margin(kExact));
  tally.worst = std::max(tally.worst, std::abs(gapOf(q) - d.distance));
  if (d.distance > kExact) {
    REQUIRE_FALSE(q.overlapping);
    ++tally.apart;
  }
}

}  // namespace

TEST_CASE("support query: sphere pairs against the closed forms", "[support]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 1);
  int apart = 0, overlapping = 0;
  double worst_gap = 0, worst_normal = 0;
  for (int i = 0; i < 2000; ++i) {
    const double ra = size(rng), rb = size(rng);
    const Vector3d ca(u(rng), u(rng), u(rng)), cb(u(rng), u(rng), u(rng));
    // Half the queries start from the centres (GJK's first direction is then the answer's), half
    // from other interior points.
    const bool at_centres = i % 2 == 0;
    const Vector3d ia = at_centres ? ca : insideBall(rng, ca, 0.9 * ra);
    const Vector3d ib = at_centres ? cb : insideBall(rng, cb, 0.9 * rb);
    const SupportMapping a = sphere(ca, ra), b = sphere(cb, rb);
    const SupportQuery q = query(a, b, ia, ib);
    const double gap = (cb - ca).norm() - ra - rb;
    const Vector3d n = (cb - ca).normalized();
    INFO("ra " << ra << " rb " << rb << " gap " << gap);
    REQUIRE(q.overlapping == (gap <= 0));
    (q.overlapping ? overlapping : apart)++;
    CHECK(gapOf(q) == Approx(gap).margin(kExact));
    CHECK((q.normal - n).norm() < kExact);
    CHECK((q.point_a - (ca + ra * n)).norm() < kExact);
    CHECK((q.point_b - (cb - rb * n)).norm() < kExact);
    worst_gap = std::max(worst_gap, std::abs(gapOf(q) - gap));
    worst_normal = std::max(worst_normal, (q.normal - n).norm());
  }
  CHECK(apart > 500);
  CHECK(overlapping > 500);
  WARN("sphere pairs: worst distance/depth error " << worst_gap << " m, worst normal error " << worst_normal);
}

TEST_CASE("support query: deep and concentric sphere overlaps", "[support]") {
  // A deep overlap makes EPA refine its whole polytope before its nearest face is within the
  // tolerance; the polish then finds the exact normal from EPA's best direction.
  for (const double offset : {0.0, 1e-9, 1e-3, 0.05, 0.2}) {
    const Vector3d ca(0.1, -0.2, 0.3), cb = ca + offset * Vector3d(1, 2, 2) / 3;
    const SupportQuery q = query(sphere(ca, 0.5), sphere(cb, 0.7), ca, cb);
    INFO("offset " << offset);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(1.2 - offset).margin(kExact));
    if (offset >= 1e-3) CHECK((q.normal - (cb - ca).normalized()).norm() < kExact);
  }
}

TEST_CASE("support query: box pairs against the SAT depth and the GJK distance", "[support]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 0.6);
  OracleTally tally;
  for (int i = 0; i < 600; ++i) {
    const ConvexPiece pa = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const ConvexPiece pb = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const CollisionHull ha = makeCollisionHull(pa), hb = makeCollisionHull(pb);
    const auto xa = pose(Vector3d(u(rng), u(rng), u(rng)), randomRotation(rng));
    // Mostly overlapping: B's centre within 0.8 of the pair's reach of A's.
    const Vector3d offset = randomUnit(rng) * (ha.radius + hb.radius) * 0.8 * std::abs(u(rng));
    const auto xb = pose(xa.translation() + offset, randomRotation(rng));
    const SupportMapping a = polytope(worldVertices(pa, xa)), b = polytope(worldVertices(pb, xb));
    INFO("trial " << i);
    compareWithOracles(query(a, b, xa.translation(), xb.translation()), ha, xa, hb, xb, tally);
  }
  CHECK(tally.overlapping > 300);
  CHECK(tally.apart > 50);
  WARN("box pairs: worst distance/depth error against the oracles " << tally.worst << " m");
}

TEST_CASE("support query: random polyhedron pairs against the SAT depth and the GJK distance", "[support]") {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1, 1), size(0.2, 0.7);
  OracleTally tally;
  long calls = 0;
  for (int i = 0; i < 400; ++i) {
    auto cloud = [&](double r) {
      std::vector<Vector3d> pts;
      for (int k = 0; k < 8 + int(rng() % 24); ++k) pts.push_back(insideBall(rng, Vector3d::Zero(), r));
      return convexHull(pts, nullptr);
    };
    const std::optional<ConvexPiece> pa = cloud(size(rng)), pb = cloud(size(rng));
    REQUIRE(pa);
    REQUIRE(pb);
    const CollisionHull ha = makeCollisionHull(*pa), hb = makeCollisionHull(*pb);
    const auto xa = pose(Vector3d(u(rng), u(rng), u(rng)), randomRotation(rng));
    const Vector3d offset = randomUnit(rng) * (ha.radius + hb.radius) * 0.9 * std::abs(u(rng));
    const auto xb = pose(xa.translation() + offset, randomRotation(rng));
    const SupportMapping a = polytope(worldVertices(*pa, xa)), b = polytope(worldVertices(*pb, xb));
    INFO("trial " << i);
    // Interior points: the vertex means.
    const SupportQuery q = supportQuery(counted(a, calls), b, xa * ha.centroid, xb * hb.centroid, kTolerance);
    checkConsistent(q, a, b);
    compareWithOracles(q, ha, xa, hb, xb, tally);
  }
  CHECK(tally.overlapping > 200);
  CHECK(tally.apart > 50);
  WARN("polyhedron pairs: worst distance/depth error against the oracles " << tally.worst << " m; "
       << double(calls) / 400 << " supports per query");
}

TEST_CASE("support query: a cylinder standing and tilted on a box's face", "[support]") {
  // The box's top face is z = 0, far wider than the cylinder: a half-space for it.
  const Vector3d half(5, 5, 1);
  const SupportMapping box = polytope(worldVertices(makeBox(half), pose({0, 0, -1})));
  const Vector3d box_centre(0, 0, -1);
  const double R = 0.4, h = 0.6;
  for (const double tilt : {0.0, 0.3, 1.2, kPi / 2}) {
    // Axis tilted about x; the lowest point of the cylinder is h |u_z| + R sqrt(1 - u_z^2) below
    // its centre: an end of the axis, then down its rim's radius across the axis.
    const Vector3d axis(0, std::sin(tilt), std::cos(tilt));
    const double below = h * std::abs(axis.z()) + R * std::sqrt(1 - axis.z() * axis.z());
    for (const double gap : {1e-3, -1e-3, 0.0, 0.2, -0.2}) {
      const Vector3d c(0.3, -0.2, below + gap);
      const SupportMapping cyl = cylinder(c, axis, R, h);
      INFO("tilt " << tilt << " gap " << gap);
      const SupportQuery q = query(box, cyl, box_centre, c);
      CHECK(gapOf(q) == Approx(gap).margin(kExact));
      CHECK((q.normal - Vector3d::UnitZ()).norm() < kExact);
      if (gap == 0) CHECK(q.overlapping);   // touching: overlapping by nothing
      else CHECK(q.overlapping == (gap < 0));
      // Where the lowest point is unique (a tilted rim), it is B's point.
      if (tilt > 0 && tilt < kPi / 2) {
        const Vector3d lowest = c - h * axis + R * across(-Vector3d::UnitZ(), axis);
        CHECK((q.point_b - lowest).norm() < kExact);
      }
      // The other order: the normal turns over.
      const SupportQuery r = query(cyl, box, c, box_centre);
      CHECK(gapOf(r) == Approx(gap).margin(kExact));
      CHECK((r.normal + Vector3d::UnitZ()).norm() < kExact);
    }
  }
}

TEST_CASE("support query: a cylinder against a sphere at its cap, its side and its rim", "[support]") {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  const double R = 0.4, h = 0.6, r = 0.25;
  for (int i = 0; i < 50; ++i) {
    // The cylinder's frame: centre c, axis e3 = u, e1 across it.
    const Vector3d c(u(rng), u(rng), u(rng)), axis = randomUnit(rng);
    const Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
    const SupportMapping cyl = cylinder(c, axis, R, h);
    const double angle = kPi * u(rng);
    const Vector3d radial = std::cos(angle) * e1 + std::sin(angle) * e2;
    const double gap = 0.05 * u(rng);
    struct Case {
      Vector3d centre, normal;   // the sphere's centre, the answer's normal (cylinder to sphere)
    };
    // Above the cap (well inside its rim), beside the side (well between the caps), and off the
    // rim along a direction 35 degrees from the axis.
    const Vector3d rim = c + h * axis + R * radial, off_rim = (std::cos(0.6) * axis + std::sin(0.6) * radial);
    const Case cases[] = {
        {c + 0.1 * radial + (h + r + gap) * axis, axis},
        {c + (R + r + gap) * radial + 0.2 * axis, radial},
        {rim + (r + gap) * off_rim, off_rim},
    };
    for (const Case& k : cases) {
      INFO("trial " << i << " case " << (&k - cases) << " gap " << gap);
      const SupportMapping ball = sphere(k.centre, r);
      const SupportQuery q = query(cyl, ball, c, k.centre);
      CHECK(q.overlapping == (gap <= 0));
      CHECK(gapOf(q) == Approx(gap).margin(kExact));
      CHECK((q.normal - k.normal).norm() < kExact);
      CHECK((q.point_b - (k.centre - r * k.normal)).norm() < kExact);
    }
  }
  SECTION("touching exactly: a sphere resting on the cap and on the rim") {
    const Vector3d c(0.2, 0.1, -0.3);
    const SupportMapping cyl = cylinder(c, Vector3d::UnitZ(), R, h);
    for (const Vector3d& s : {Vector3d(c + Vector3d(0.1, 0.05, h + r)), Vector3d(c + Vector3d(R, 0, h) + r * Vector3d(0.6, 0, 0.8))}) {
      const SupportQuery q = query(cyl, sphere(s, r), c, s);
      CHECK(std::abs(gapOf(q)) < kExact);
    }
  }
}

TEST_CASE("support query: coincident centres", "[support]") {
  const Vector3d c(0.3, -0.1, 0.2);
  SECTION("a squat cylinder and a sphere: out through a cap") {
    // h < R: the least way out is along the axis, r + h.
    const SupportQuery q = query(cylinder(c, Vector3d::UnitZ(), 0.5, 0.2), sphere(c, 0.3), c, c);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(0.5).margin(kExact));
    CHECK(std::abs(std::abs(q.normal.z()) - 1) < kExact);
  }
  SECTION("a box and a sphere: out through the nearest face") {
    const SupportQuery q = query(polytope(worldVertices(makeBox({0.5, 0.3, 0.4}), pose(c))), sphere(c, 0.1), c, c);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(0.4).margin(kExact));
    CHECK(std::abs(std::abs(q.normal.y()) - 1) < kExact);
  }
  SECTION("two equal boxes: out through any face") {
    const SupportMapping box = polytope(worldVertices(makeBox({0.5, 0.5, 0.5}), pose(c)));
    const SupportQuery q = query(box, box, c, c);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(1.0).margin(kExact));
    CHECK(std::abs(q.normal.cwiseAbs().maxCoeff() - 1) < kExact);
  }
  SECTION("a tall cylinder and a sphere: out through the side, any way round") {
    // Every direction across the axis is a least way out (r + R): EPA would have to refine its
    // polytope all round the axis to certify it, and its iteration cap stops it (at a lower bound
    // 1.4e-5 short); its best probe, polished across the side's edge, is exact.
    const SupportQuery q = query(cylinder(c, Vector3d::UnitZ(), 0.3, 0.6), sphere(c, 0.2), c, c);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(0.5).margin(kExact));
    CHECK(std::abs(q.normal.z()) < kExact);
  }
}

TEST_CASE("support query: cones on a box's face and against a sphere", "[support]") {
  const SupportMapping box = polytope(worldVertices(makeBox({5, 5, 1}), pose({0, 0, -1})));
  const Vector3d box_centre(0, 0, -1);
  const double R = 0.3, len = 0.8;
  for (const double tilt : {0.0, 0.5, 2.0, kPi}) {
    // Base centre at the origin of the cone's frame, apex at len along its axis, tilted about x.
    const Vector3d axis(0, std::sin(tilt), std::cos(tilt));
    // Lowest point: the apex or the base's rim, whichever is lower.
    const double rim_low = -R * std::sqrt(1 - axis.z() * axis.z()), apex_low = len * axis.z();
    const double below = -std::min(rim_low, apex_low);
    for (const double gap : {1e-3, -1e-3, 0.0, -0.05}) {
      const Vector3d base(0.1, 0.2, below + gap);
      const SupportMapping k = cone(base, base + len * axis, R);
      INFO("tilt " << tilt << " gap " << gap);
      const SupportQuery q = query(box, k, box_centre, base + 0.25 * len * axis);
      CHECK(gapOf(q) == Approx(gap).margin(kExact));
      CHECK((q.normal - Vector3d::UnitZ()).norm() < kExact);
    }
  }
  // A sphere over the apex of an upright cone: the apex is the nearest point while the sphere's
  // centre lies in the apex's normal cone (within 90 degrees less the half angle of the axis).
  const Vector3d base(0, 0, 0), apex(0, 0, len);
  const SupportMapping k = cone(base, apex, R);
  for (const double gap : {0.1, 1e-3, -1e-3, -0.05}) {
    const Vector3d dir = Vector3d(0.2, 0.1, 1).normalized(), s = apex + (0.2 + gap) * dir;
    const SupportQuery q = query(k, sphere(s, 0.2), base + 0.25 * (apex - base), s);
    INFO("gap " << gap);
    CHECK(gapOf(q) == Approx(gap).margin(kExact));
    CHECK((q.normal - dir).norm() < kExact);
    CHECK((q.point_a - apex).norm() < kExact);
  }
}

TEST_CASE("support query: flat and thin sets (a disc, a segment, a point)", "[support]") {
  const Vector3d box_half(0.5, 0.3, 0.4), box_at(0.1, 0.2, 0.3);
  const SupportMapping box = polytope(worldVertices(makeBox(box_half), pose(box_at)));
  SECTION("a point in and out of a box: the box's signed distance function") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    for (int i = 0; i < 300; ++i) {
      const Vector3d p = box_at + Vector3d(u(rng), u(rng), u(rng));
      const Vector3d local = (p - box_at).cwiseAbs() - box_half;
      const double sdf = local.cwiseMax(0.0).norm() + std::min(local.maxCoeff(), 0.0);
      const SupportQuery q = query(box, point(p), box_at, p);
      CHECK(gapOf(q) == Approx(sdf).margin(kExact));
      CHECK((q.point_b - p).norm() < kExact);
    }
  }
  SECTION("a flat disc level over a box's top face, and tilted") {
    const double top = box_at.z() + box_half.z();
    for (const double tilt : {0.0, 0.4}) {
      const Vector3d n(std::sin(tilt), 0, std::cos(tilt));
      for (const double gap : {1e-3, 0.0, -1e-3, -0.1}) {
        const Vector3d c(0.1, 0.2, top + 0.1 * std::sin(tilt) + gap);   // lowest rim point at top + gap
        const SupportQuery q = query(box, disc(c, n, 0.1), box_at, c);
        INFO("tilt " << tilt << " gap " << gap);
        CHECK(gapOf(q) == Approx(gap).margin(kExact));
        CHECK((q.normal - Vector3d::UnitZ()).norm() < kExact);
      }
    }
  }
  SECTION("sets whose difference has no volume: they only touch") {
    const Vector3d c(0.2, -0.3, 0.1);
    struct Pair {
      SupportMapping a, b;
      Vector3d ca, cb;
    };
    const Pair pairs[] = {
        {point(c), point(c), c, c},                                                              // the same point
        {point(c), segment(c - Vector3d(0.2, 0.1, 0), c + Vector3d(0.4, 0.2, 0)), c, c},           // a point on a segment
        {segment(c - Vector3d::UnitX(), c + Vector3d::UnitX()), segment(c - Vector3d::UnitY(), c + Vector3d::UnitY()), c, c},
        {disc(c, Vector3d::UnitZ(), 0.5), point(c + Vector3d(0.1, 0.2, 0)), c, c + Vector3d(0.1, 0.2, 0)},
        {disc(c, Vector3d::UnitZ(), 0.5), disc(c + Vector3d(0.3, 0, 0), Vector3d::UnitZ(), 0.4), c, c + Vector3d(0.3, 0, 0)},
        {disc(c, Vector3d::UnitZ(), 0.5), segment(c - Vector3d(1, 0, 0), c + Vector3d(1, 0.1, 0)), c, c},
    };
    for (const Pair& p : pairs) {
      const SupportQuery q = query(p.a, p.b, p.ca, p.cb);
      CHECK(q.overlapping);
      CHECK(q.depth < kExact);
    }
    // Coplanar discs part across their plane, the thinnest way.
    const SupportQuery q = query(disc(c, Vector3d::UnitZ(), 0.5), disc(c, Vector3d::UnitZ(), 0.4), c, c);
    CHECK(std::abs(std::abs(q.normal.z()) - 1) < kExact);
  }
  SECTION("a segment through a box: its depth is the least push out across it") {
    // A segment along x through the box's middle, longer than the box: out along y (0.3).
    const SupportQuery q = query(box, segment(box_at - Vector3d(1, 0, 0), box_at + Vector3d(1, 0, 0)), box_at, box_at);
    REQUIRE(q.overlapping);
    CHECK(q.depth == Approx(0.3).margin(kExact));
    CHECK(std::abs(std::abs(q.normal.y()) - 1) < kExact);
  }
}

namespace {

// A random set of any kind about the origin-centred frame x, and an interior point of it.
struct AnySet {
  SupportMapping support;
  Vector3d centre;
};

AnySet randomSet(std::mt19937& rng, int kind, const Eigen::Isometry3d& x) {
  std::uniform_real_distribution<double> size(0.05, 0.8);
  const Vector3d c = x.translation(), axis = x.linear().col(2);
  switch (kind) {
    case 0: return {sphere(c, size(rng)), c};
    case 1: return {polytope(worldVertices(makeBox(Vector3d(size(rng), size(rng), size(rng))), x)), c};
    case 2: {
      std::vector<Vector3d> pts;
      for (int k = 0; k < 12; ++k) pts.push_back(insideBall(rng, c, size(rng)));
      Vector3d mean = Vector3d::Zero();
      for (const Vector3d& p : pts) mean += p / 12;
      return {polytope(pts), mean};
    }
    case 3: return {cylinder(c, axis, size(rng), size(rng)), c};
    case 4: {
      const double len = size(rng);
      return {cone(c, c + len * axis, size(rng)), c + 0.25 * len * axis};
    }
    case 5: return {disc(c, axis, size(rng)), c};
    case 6: {
      const double len = size(rng);
      return {segment(c - len * axis, c + len * axis), c};
    }
    default: return {point(c), c};
  }
}

}  // namespace

TEST_CASE("support query: never NaN, consistent and deterministic over random pairs of every kind", "[support]") {
  std::mt19937 rng(59);
  std::uniform_real_distribution<double> u(-1, 1);
  constexpr int kKinds = 8;
  int overlapping = 0;
  double worst_plane = 0, worst_along = 0;
  for (int i = 0; i < 4000; ++i) {
    const int ka = int(rng() % kKinds), kb = int(rng() % kKinds);
    const auto xa = pose(Vector3d(u(rng), u(rng), u(rng)), randomRotation(rng));
    // A quarter with coincident centres, the rest within reach of each other.
    const auto xb = i % 4 == 0 ? pose(xa.translation(), randomRotation(rng))
                               : pose(xa.translation() + 0.6 * Vector3d(u(rng), u(rng), u(rng)),
                                      randomRotation(rng));
    const AnySet a = randomSet(rng, ka, xa), b = randomSet(rng, kb, xb);
    INFO("trial " << i << " kinds " << ka << " " << kb);
    const SupportQuery q = query(a.support, b.support, a.centre, b.centre);
    overlapping += q.overlapping;
    // Bounds any answer obeys: moving B by depth x normal leaves no overlap deeper than the
    // tolerance (the support of A - B along the normal is at most the depth), and apart, the
    // normal is a separating direction at the distance.
    const Vector3d along = a.support(q.normal) - b.support(-q.normal);
    const double excess = q.normal.dot(along) - (q.overlapping ? q.depth : -q.distance);
    CHECK(std::abs(excess) < kExact);
    worst_along = std::max(worst_along, std::abs(excess));
    worst_plane = std::max({worst_plane, std::abs(q.normal.dot(a.support(q.normal) - q.point_a)),
                            std::abs(q.normal.dot(b.support(-q.normal) - q.point_b))});
    // Deterministic: the same query again gives the same bits.
    const SupportQuery again = supportQuery(a.support, b.support, a.centre, b.centre, kTolerance);
    CHECK(again.overlapping == q.overlapping);
    CHECK(std::memcmp(&again.distance, &q.distance, sizeof(double)) == 0);
    CHECK(std::memcmp(&again.depth, &q.depth, sizeof(double)) == 0);
    CHECK(std::memcmp(again.normal.data(), q.normal.data(), 3 * sizeof(double)) == 0);
    CHECK(std::memcmp(again.point_a.data(), q.point_a.data(), 3 * sizeof(double)) == 0);
    CHECK(std::memcmp(again.point_b.data(), q.point_b.data(), 3 * sizeof(double)) == 0);
  }
  CHECK(overlapping > 1000);
  WARN("random pairs: worst support excess along the normal " << worst_along << " m, worst point off its plane " << worst_plane << " m");
}

TEST_CASE("support query: iterations and time per query", "[support]") {
  // Not checked: printed for tuning. Support evaluations of A per query: one per GJK or EPA
  // iteration, up to 12 per Newton step of the polish.
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> u(-1, 1), size(0.2, 0.6);
  struct Tally {
    long queries = 0, calls = 0, worst = 0;
    double seconds = 0;
  };
  Tally tallies[3][2];   // sphere pairs, cylinder-sphere, cylinder-box; apart, overlapping
  for (int i = 0; i < 3000; ++i) {
    const int kind = i % 3;
    const Vector3d ca(u(rng), u(rng), u(rng)), cb = ca + 0.9 * Vector3d(u(rng), u(rng), u(rng));
    const double ra = size(rng), rb = size(rng);
    long calls = 0;
    SupportMapping a = kind == 0 ? sphere(ca, ra) : cylinder(ca, randomUnit(rng), ra, size(rng));
    SupportMapping b = kind == 2 ? polytope(worldVertices(makeBox(Vector3d(rb, rb, rb)), pose(cb, randomRotation(rng))))
                                 : sphere(cb, rb);
    a = counted(std::move(a), calls);
    const auto start = std::chrono::steady_clock::now();
    const SupportQuery q = supportQuery(a, b, insideBall(rng, ca, 0.1), cb, kTolerance);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Tally& t = tallies[kind][q.overlapping];
    ++t.queries;
    t.calls += calls;
    t.worst = std::max(t.worst, calls);
    t.seconds += seconds;
  }
  const char* names[3] = {"sphere-sphere", "cylinder-sphere", "cylinder-box"};
  for (int k = 0; k < 3; ++k)
    for (int o = 0; o < 2; ++o) {
      const Tally& t = tallies[k][o];
      if (t.queries == 0) continue;
      WARN(names[k] << (o ? " overlapping: " : " apart: ") << t.queries << " queries, "
           << double(t.calls) / t.queries << " supports on average (at most " << t.worst << "), "
           << 1e6 * t.seconds / t.queries << " us per query");
    }
}
