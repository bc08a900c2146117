// separation() must never exceed the true distance (conservative advancement relies on it).
// The oracle: for disjoint convex polyhedra the closest points lie on a vertex-face or an
// edge-edge pair, so the distance is the least over vertices projecting inside a face of their
// plane distance, and over edge pairs of their segment distance.
#include <catch2/catch.hpp>

#include <random>

#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;

namespace {

double pointSegment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// The distance from a point of segment 1 to segment 2 is convex along segment 1: ternary search.
double segmentSegment(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 100; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (pointSegment(a + m1 * (b - a), c, d) < pointSegment(a + m2 * (b - a), c, d)) hi = m2;
    else lo = m1;
  }
  return pointSegment(a + lo * (b - a), c, d);
}

std::vector<Vector3d> worldVertices(const ConvexPiece& p, const Eigen::Isometry3d& x) {
  std::vector<Vector3d> v;
  for (const Vector3d& q : p.vertices) v.push_back(x * q);
  return v;
}

double vertexFace(const ConvexPiece& a, const Eigen::Isometry3d& xa, const ConvexPiece& b,
                  const Eigen::Isometry3d& xb) {
  const auto va = worldVertices(a, xa), vb = worldVertices(b, xb);
  double best = INFINITY;
  for (size_t f = 0; f < b.faces.size(); ++f) {
    const Vector3d n = xb.linear() * b.face_normals[f];
    const auto& face = b.faces[f];
    for (const Vector3d& p : va) {
      bool inside = true;
      for (size_t k = 0; k < face.size(); ++k) {
        const Vector3d e = vb[face[(k + 1) % face.size()]] - vb[face[k]];
        inside = inside && e.cross(n).dot(p - vb[face[k]]) <= 0;
      }
      if (inside) best = std::min(best, std::abs(n.dot(p - vb[face[0]])));
    }
  }
  return best;
}

double bruteDistance(const ConvexPiece& a, const Eigen::Isometry3d& xa, const ConvexPiece& b,
                     const Eigen::Isometry3d& xb) {
  double best = std::min(vertexFace(a, xa, b, xb), vertexFace(b, xb, a, xa));
  const auto va = worldVertices(a, xa), vb = worldVertices(b, xb);
  for (const auto& [i, j] : a.edges) {
    for (const auto& [k, l] : b.edges) best = std::min(best, segmentSegment(va[i], va[j], vb[k], vb[l]));
  }
  return best;
}

}  // namespace

TEST_CASE("separation: a lower bound on the distance of random separated boxes", "[narrow][separation]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 0.6);
  int separated = 0, tight = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ConvexPiece a = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const ConvexPiece b = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const CollisionHull ha = makeCollisionHull(a), hb = makeCollisionHull(b);
    const double reach = ha.radius + hb.radius;
    const Vector3d dir = Vector3d(u(rng), u(rng), u(rng)).normalized();
    const auto xa = pose(Vector3d(u(rng), u(rng), u(rng)), Eigen::Quaterniond::UnitRandom());
    const auto xb = pose(xa.translation() + dir * reach * (0.5 + 0.7 * std::abs(u(rng))),
                         Eigen::Quaterniond::UnitRandom());
    SatCache cache;
    const double s = separation(ha, xa, hb, xb, cache);
    if (s <= 0) continue;  // SAT proves nothing about the distance of overlapping pairs
    ++separated;
    const double dist = bruteDistance(a, xa, b, xb);
    REQUIRE(s <= dist + 1e-12);
    if (s > dist - 1e-9) ++tight;
    // agrees with collide: no contact beyond the SAT value
    SatCache other;
    CHECK_FALSE(collide(ha, xa, hb, xb, 0.99 * s, other));
  }
  CHECK(separated > 200);
  CHECK(tight > separated / 2);  // face-vertex and edge-edge closest pairs: exact
}

TEST_CASE("separation: exact for a face-face gap", "[narrow][separation]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const CollisionHull h = makeCollisionHull(box);
  SatCache cache;
  CHECK(separation(h, Eigen::Isometry3d::Identity(), h, pose({0.3, 0.1, 1.25}), cache) ==
        Approx(0.25).epsilon(1e-12));
  CHECK(separation(h, Eigen::Isometry3d::Identity(), h, pose({0.3, 0.1, 0.75}), cache) ==
        Approx(-0.25).epsilon(1e-12));
}

// GJK's distance stops at rounding, which on a large face under a nearly parallel small one can
// be a thousand times the face's gap: a 0.3 m box lying on a 4 m ramp 1.01e-7 m apart came out
// 1.02e-7 m apart. Taken for a pair closest at a vertex, it got one point, turned about it and
// sank two corners 1.25 mm into the ramp within a step (the slope jumble, time stepping).
TEST_CASE("collide: a box lying a hair above a large tilted slab is a face contact with its four corners",
          "[narrow][separation]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  const ConvexPiece slab = makeBox(Vector3d(2, 1.5, 0.15));   // half extents: 4 x 3 x 0.3 m
  const CollisionHull hs = makeCollisionHull(slab);
  int closest_points = 0, trials = 300;
  for (int trial = 0; trial < trials; ++trial) {
    const ConvexPiece box = makeBox(Vector3d(0.025 + 0.15 * unit(rng), 0.025 + 0.15 * unit(rng), 0.025 + 0.15 * unit(rng)));
    const CollisionHull hb = makeCollisionHull(box);
    const Eigen::Quaterniond slope = test::rotation(0.5 * u(rng), Vector3d(u(rng), u(rng), 0));
    const auto xs = pose(Vector3d(u(rng), u(rng), 0.8), slope);
    // The box's -z face down on the slab's +z face, turned about the normal, tilted by up to
    // 1e-7 rad, its lowest corner 1e-8 to 5e-7 m above (within the contact tolerance of 1e-6 m).
    const Eigen::Quaterniond lie = slope * test::rotation(1e-7 * unit(rng), Vector3d(u(rng), u(rng), 0)) *
                                   test::rotation(3.2 * u(rng), Vector3d::UnitZ());
    Eigen::Isometry3d xb = pose(xs * Vector3d(1.5 * u(rng), 1.0 * u(rng), 0.5), lie);
    const Vector3d up = slope * Vector3d::UnitZ();
    double lowest = INFINITY;
    for (const Vector3d& v : box.vertices) lowest = std::min(lowest, up.dot(xb * v - xs.translation()) - 0.15);
    const double gap = 1e-8 + 4.9e-7 * unit(rng);
    xb.translation() += (gap - lowest) * up;
    SatCache cache;
    const auto m = collide(hs, xs, hb, xb, 1e-3, cache);
    REQUIRE(m);
    if (m->closest_points) ++closest_points;
    CHECK(m->points.size() == 4);
    CHECK(m->normal.dot(up) == Approx(1).margin(1e-9));
    // Each corner at its own height: the gap, plus at most the tilt times the box's size (1e-7 m).
    for (const ContactPoint& p : m->points) {
      CHECK(p.depth <= -gap + 1e-12);
      CHECK(p.depth >= -gap - 1e-7);
    }
  }
  CHECK(closest_points == 0);
}

// Two equal faces turned a little against each other across a small gap (the halves of a cut
// brick after a blow): the separating axis is an edge pair's, or the direction between the closest
// points, a few milliradians off the faces' normal. Held at that one corner, the halves turned into
// each other within a step; the contact is the faces' clipped overlap.
TEST_CASE("collide: equal faces turned by milliradians across a small gap meet at their whole overlap, not one corner",
          "[narrow][separation]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  int off_face_axis = 0, edge_axis = 0, trials = 300;
  for (int trial = 0; trial < trials; ++trial) {
    const Vector3d half(0.05 + 0.15 * unit(rng), 0.05 + 0.15 * unit(rng), 0.05 + 0.3 * unit(rng));
    const ConvexPiece box = makeBox(half);
    const CollisionHull h = makeCollisionHull(box);
    const auto xa = pose(Vector3d::Zero());
    // B on A's top face, tilted by 1e-3 to 1.2e-2 rad (within the 0.8 degrees of kOppositeFaces)
    // about an axis in the face, turned by 0.01 to 0.1 rad about the normal and shifted sideways by up
    // to 1 cm: the two outlines cross, and where B hangs past A's face its corners reach below A's
    // plane (and A's below B's), so that neither face's own separation is the pair's; inside
    // the overlap B stands 1e-7 to 5e-5 m above A.
    const Eigen::Quaterniond turn = test::rotation(1e-3 + 1.1e-2 * unit(rng), Vector3d(u(rng), u(rng), 0)) *
                                    test::rotation((0.01 + 0.09 * unit(rng)) * (u(rng) < 0 ? -1 : 1), Vector3d::UnitZ());
    Eigen::Isometry3d xb = pose(Vector3d(0.01 * u(rng), 0.01 * u(rng), 2 * half.z()), turn);
    const double gap = 1e-7 + 5e-5 * unit(rng);
    for (int k = 0; k < 4; ++k) {   // the SAT's axis is within milliradians of z: a few corrections
      SatCache fit;
      xb.translation().z() += gap - separation(h, xa, h, xb, fit);
    }
    SatCache probe;
    Vector3d axis;
    const double sat = separation(h, xa, h, xb, probe, axis);
    if (std::abs(axis.z()) < 1 - 1e-9) ++off_face_axis;   // the SAT's best axis is not the face's
    if (probe.axis == SatCache::Axis::Edges) ++edge_axis;
    SatCache cache;
    const auto m = collide(h, xa, h, xb, 1e-3, cache);
    REQUIRE(m);
    CHECK_FALSE(m->closest_points);
    // The faces' overlap: B's bottom face seen from above, clipped to A's top face; each corner of
    // it within the margin of A's face (less a share for rounding) must make a point, up to three.
    const Vector3d down = turn * Vector3d(0, 0, -1);   // B's bottom face: down . p = offset
    std::vector<Eigen::Vector2d> overlap;
    double offset = 0;
    for (const Vector3d& v : box.vertices)
      if (v.z() < 0) overlap.push_back((xb * v).head<2>()), offset = down.dot(xb * v);
    const Eigen::Vector2d mid = 0.25 * (overlap[0] + overlap[1] + overlap[2] + overlap[3]);
    std::sort(overlap.begin(), overlap.end(), [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
      return std::atan2(p.y() - mid.y(), p.x() - mid.x()) < std::atan2(q.y() - mid.y(), q.x() - mid.x());
    });
    for (int side = 0; side < 4; ++side) {   // Sutherland-Hodgman against x <= hx, -x <= hx, y <= hy, -y <= hy
      const Eigen::Vector2d n = side < 2 ? Eigen::Vector2d(side == 0 ? 1 : -1, 0) : Eigen::Vector2d(0, side == 2 ? 1 : -1);
      const double limit = side < 2 ? half.x() : half.y();
      std::vector<Eigen::Vector2d> kept;
      for (std::size_t k = 0; k < overlap.size(); ++k) {
        const Eigen::Vector2d& p = overlap[k];
        const Eigen::Vector2d& q = overlap[(k + 1) % overlap.size()];
        const double dp = n.dot(p) - limit, dq = n.dot(q) - limit;
        if (dp <= 0) kept.push_back(p);
        if ((dp < 0) != (dq < 0) && dp != dq) kept.push_back(p + (q - p) * (dp / (dp - dq)));
      }
      overlap = kept;
    }
    int near = 0;
    for (const Eigen::Vector2d& p : overlap) {
      const double z = (offset - down.x() * p.x() - down.y() * p.y()) / down.z();
      near += z - half.z() < 0.9e-3;
    }
    CHECK(m->points.size() >= std::size_t(std::min(near, 3)));
    CHECK(std::abs(m->normal.z()) > 0.9999);
    double deepest = -INFINITY;
    for (const ContactPoint& p : m->points) deepest = std::max(deepest, p.depth);
    // As deep as the pair is apart, within kParallelSine (1e-6) of the size (0.5 m at most here):
    // the two directions measure the same gap to that.
    CHECK(deepest == Approx(-std::max(sat, 0.0)).margin(5e-7));
  }
  INFO(off_face_axis << " poses with the best axis off the face normal, " << edge_axis << " an edge pair's");
  CHECK(off_face_axis > trials / 4);
  CHECK(edge_axis > trials / 4);
}

TEST_CASE("collide(A, B) and collide(B, A) agree up to the normal's sign", "[narrow]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const ConvexPiece a = makeBox(Vector3d(0.5, 0.3, 0.2)), b = makeBox(Vector3d(0.4, 0.4, 0.1));
  int contacts = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto xa = pose(Vector3d::Zero(), Eigen::Quaterniond::UnitRandom());
    const auto xb = pose(0.6 * Vector3d(u(rng), u(rng), u(rng)), Eigen::Quaterniond::UnitRandom());
    SatCache c1, c2;
    const auto ab = collide(a, xa, b, xb, 0.0, c1), ba = collide(b, xb, a, xa, 0.0, c2);
    REQUIRE(bool(ab) == bool(ba));
    if (!ab) continue;
    ++contacts;
    for (const auto* m : {&*ab, &*ba}) {
      REQUIRE(m->normal.allFinite());
      for (const ContactPoint& p : m->points) REQUIRE(p.position.allFinite());
    }
    double da = 0, db = 0;
    for (const ContactPoint& p : ab->points) da = std::max(da, p.depth);
    for (const ContactPoint& p : ba->points) db = std::max(db, p.depth);
    // both are the SAT depth (test_manifold_depth.cpp), whichever feature each call chose
    CHECK(da == Approx(db).margin(2e-9 * 0.8));
  }
  CHECK(contacts > 50);
}

// pieceDistance (GJK) against the same oracle, and what collide makes of pairs the SAT value
// underestimates: one contact at the closest points, with the true distance.
TEST_CASE("distance: GJK gives the distance and closest points of random separated boxes", "[narrow][distance]") {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 0.6);
  int separated = 0, underestimated = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ConvexPiece a = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const ConvexPiece b = makeBox(Vector3d(size(rng), size(rng), size(rng)));
    const CollisionHull ha = makeCollisionHull(a), hb = makeCollisionHull(b);
    const Vector3d dir = Vector3d(u(rng), u(rng), u(rng)).normalized();
    const auto xa = pose(Vector3d(u(rng), u(rng), u(rng)), Eigen::Quaterniond::UnitRandom());
    const auto xb = pose(xa.translation() + dir * (ha.radius + hb.radius) * (0.5 + 0.7 * std::abs(u(rng))),
                         Eigen::Quaterniond::UnitRandom());
    SatCache cache;
    const double s = separation(ha, xa, hb, xb, cache);
    if (s <= 0) continue;
    ++separated;
    const double dist = bruteDistance(a, xa, b, xb);
    const PieceDistance d = pieceDistance(ha, xa, hb, xb);
    // 1e-9 m: rounding on coordinates of order 1 m, far below any contact tolerance
    REQUIRE(d.distance == Approx(dist).margin(1e-9));
    CHECK((d.point_b - d.point_a).norm() == Approx(dist).margin(1e-9));
    // The closest points lie on the pieces: inside or on every face plane.
    for (size_t f = 0; f < a.faces.size(); ++f)
      CHECK((xa.linear() * a.face_normals[f]).dot(d.point_a - xa * a.vertices[a.faces[f][0]]) < 1e-9);
    for (size_t f = 0; f < b.faces.size(); ++f)
      CHECK((xb.linear() * b.face_normals[f]).dot(d.point_b - xb * b.vertices[b.faces[f][0]]) < 1e-9);
    SatCache other;
    const auto m = collide(ha, xa, hb, xb, dist + 1e-3, other);
    REQUIRE(m);
    if (dist > s + 1e-6) {
      ++underestimated;
      CHECK(m->closest_points);
      REQUIRE(m->points.size() == 1);
      CHECK(m->points[0].depth == Approx(-dist).margin(1e-9));
      CHECK(m->normal.dot(d.point_b - d.point_a) == Approx(dist).margin(1e-9));
    }
    SatCache beyond;
    CHECK_FALSE(collide(ha, xa, hb, xb, 0.99 * dist, beyond));   // farther than the margin: none
  }
  CHECK(separated > 200);
  CHECK(underestimated > 20);
}
