// A kept manifold reused at a moved pose against the narrow phase run afresh there: exact for a
// box's corners on a face, and its drift bound never below how far a corner really moved.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "collision/collision_hull.h"
#include "collision/kept_manifold.h"
#include "collision/narrow_phase.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::deepestDepth;
using test::pose;
using test::rotation;

namespace {

const ContactPoint* withFeature(const ContactManifold& m, std::uint32_t feature) {
  for (const ContactPoint& p : m.points)
    if (p.feature == feature) return &p;
  return nullptr;
}

// The kept manifold reused at `moved` against the narrow phase run afresh there: the same points
// (by feature), the same normal, and each depth the same to the rounding of the transforms (1e-12 m
// on a metre-sized pair). Returns the largest distance between a reused point and its fresh one.
double checkReusedIsFresh(const KeptManifold& kept, const CollisionHull& base, const Eigen::Isometry3d& pose_a,
                          const CollisionHull& top, const Eigen::Isometry3d& moved, double margin) {
  ContactManifold reused, fresh;
  REQUIRE(reuseManifold(kept, pose_a, moved, ReferenceIs::A, margin, reused));
  SatCache fresh_cache;
  REQUIRE(collide(base, pose_a, top, moved, margin, fresh_cache, fresh));
  REQUIRE(reused.points.size() == fresh.points.size());
  CHECK((reused.normal - fresh.normal).norm() < 1e-12);
  double apart = 0;
  for (const ContactPoint& p : reused.points) {
    const ContactPoint* q = withFeature(fresh, p.feature);
    REQUIRE(q != nullptr);
    CHECK(std::abs(p.depth - q->depth) < 1e-12);
    apart = std::max(apart, (p.position - q->position).norm());
  }
  return apart;
}

// A 0.5 m box (B) over a slab 2 m wide and 0.5 m thick (A) whose top face is the plane z = 0.5.
struct BoxOverSlab {
  ConvexPiece base_shape = makeBox(Vector3d(1.0, 1.0, 0.25));
  ConvexPiece top_shape = makeBox(Vector3d(0.25, 0.25, 0.25));
  CollisionHull base = makeCollisionHull(base_shape), top = makeCollisionHull(top_shape);
  Eigen::Isometry3d pose_a = pose({0, 0, 0.25});
};

}  // namespace

TEST_CASE("kept manifold: a box resting on a box, moved within the slack, gives the narrow phase's depths",
          "[kept_manifold]") {
  const BoxOverSlab scene;
  const auto& [base_shape, top_shape, base, top, pose_a] = scene;
  const Eigen::Isometry3d built_at = pose({0.1, -0.05, 0.75 - 2e-7}, rotation(0.3, Vector3d::UnitZ()));
  const double margin = 1e-3, slack = 1e-4;
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(base, pose_a, top, built_at, margin, cache, m));
  REQUIRE(m.points.size() == 4);
  KeptManifold kept;
  const Eigen::Isometry3d rel0 = pose_a.inverse(Eigen::Isometry) * built_at;
  keepManifold(m, true, pose_a, built_at, rel0, ReferenceIs::A, &base_shape, top_shape, margin, kept);
  REQUIRE(kept.valid);

  // Slid, sunk and tilted by less than the slack: every corner stays a corner on the base's face,
  // so each reused depth is the corner's distance to the face plane, the narrow phase's own.
  const Eigen::Isometry3d moved =
      pose({0.1 + 3e-5, -0.05 - 2e-5, 0.75 - 5e-7}, rotation(0.3, Vector3d::UnitZ()) * rotation(5e-5, Vector3d(1, 2, 0)));
  const Eigen::Isometry3d rel = pose_a.inverse(Eigen::Isometry) * moved;
  const double drift = keptDrift(kept, rel, top.radius);
  CHECK(drift > 0);
  CHECK(drift <= slack);

  // The point on the base's face stays where the corner was: the midpoint lags by half the slide.
  CHECK(checkReusedIsFresh(kept, base, pose_a, top, moved, margin) <= 0.5 * drift);
}

TEST_CASE("kept manifold: a box on the ground keeps its corners' depths exact and drops a corner that lifts past the margin",
          "[kept_manifold]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.3, 0.2));
  const CollisionHull hull = makeCollisionHull(box);
  const Eigen::Isometry3d world = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d built_at = pose({1, 2, 0.2 - 1e-6});
  const double margin = 1e-3;
  ContactManifold m;
  REQUIRE(collideGround(box, built_at, 0.0, margin, m));
  KeptManifold kept;
  keepManifold(m, true, world, built_at, built_at, ReferenceIs::B, nullptr, box, margin, kept);
  REQUIRE(kept.count == 4);

  // Tilted about y by an angle that lifts the far corners by 1.5e-4 m.
  const double tilt = 1.5e-4 / 1.0;
  const Eigen::Isometry3d tilted = pose({1 + 0.5, 2, 0.2 - 1e-6}, rotation(-tilt, Vector3d::UnitY())) *
                                   pose({-0.5, 0, 0});
  ContactManifold reused;
  REQUIRE(reuseManifold(kept, world, tilted, ReferenceIs::B, margin, reused));
  const auto fresh = collideGround(box, tilted, 0.0, margin);
  REQUIRE(fresh);
  CHECK(std::abs(deepestDepth(reused) - deepestDepth(*fresh)) < 1e-12);
  CHECK(reused.normal == Vector3d(0, 0, -1));

  // Lifted 2 mm: every corner farther than the margin, no contact.
  ContactManifold lifted;
  CHECK_FALSE(reuseManifold(kept, world, pose({1, 2, 0.2 + 2e-3}), ReferenceIs::B, margin, lifted));
}

TEST_CASE("kept manifold: the drift bound is never below how far a vertex moved in the reference frame",
          "[kept_manifold]") {
  const ConvexPiece shape = makeBox(Vector3d(0.4, 0.2, 0.1));
  const CollisionHull hull = makeCollisionHull(shape);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const double scale = std::pow(10.0, -1 - 5 * (trial % 6) / 5.0);   // moves from 1e-1 to 1e-6
    const Eigen::Isometry3d before =
        pose({u(rng), u(rng), u(rng)}, rotation(3 * u(rng), Vector3d(u(rng), u(rng), u(rng) + 1.5)));
    const Eigen::Isometry3d after =
        pose(before.translation() + scale * Vector3d(u(rng), u(rng), u(rng)),
             Eigen::Quaterniond(before.linear()) * rotation(scale * u(rng), Vector3d(u(rng), u(rng) + 1.5, u(rng))));
    KeptManifold k;
    k.rel = before;
    const double bound = keptDrift(k, after, hull.radius);
    double moved = 0;
    for (const Vector3d& v : shape.vertices) moved = std::max(moved, (after * v - before * v).norm());
    CHECK(moved <= bound * (1 + 1e-12));
    CHECK(bound <= 4 * moved + 1e-15);   // and not far above it (sqrt 2 from the Frobenius norm, sqrt 3/2 from a box corner off the axis)
  }
}

TEST_CASE("kept manifold: a box overhanging the edge of the one below, its footprint clipped there, is not kept",
          "[kept_manifold]") {
  const ConvexPiece base_shape = makeBox(Vector3d(0.5, 0.5, 0.25));
  const ConvexPiece top_shape = makeBox(Vector3d(0.25, 0.25, 0.25));
  const CollisionHull base = makeCollisionHull(base_shape), top = makeCollisionHull(top_shape);
  const Eigen::Isometry3d pose_a = pose({0, 0, 0.25});
  // Its centre 0.1 m inside the base's edge, tilted a little about y: two of its bottom corners
  // lie beyond the edge, so two points of the manifold are where its edges cross that border.
  const Eigen::Isometry3d pose_b = pose({0.4, 0, 0.75 - 1e-6}, rotation(1e-4, Vector3d::UnitY()));
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(base, pose_a, top, pose_b, 1e-3, cache, m));
  REQUIRE(m.points.size() == 4);
  KeptManifold kept;
  keepManifold(m, true, pose_a, pose_b, pose_a.inverse(Eigen::Isometry) * pose_b, ReferenceIs::A, &base_shape,
               top_shape, 1e-3, kept);
  CHECK_FALSE(kept.valid);

  // Moved fully onto the base, every point is one of its corners: kept.
  const Eigen::Isometry3d inside = pose({0.1, 0, 0.75 - 1e-6}, rotation(1e-4, Vector3d::UnitY()));
  REQUIRE(collide(base, pose_a, top, inside, 1e-3, cache, m));
  keepManifold(m, true, pose_a, inside, pose_a.inverse(Eigen::Isometry) * inside, ReferenceIs::A, &base_shape,
               top_shape, 1e-3, kept);
  CHECK(kept.valid);
}

// A box resting on one of its edges on a box's face (tilted 0.3 rad): the manifold is that edge's
// two corners, and every other corner stands far above the face, so nothing else of the pair is
// within the margin and drift within the slack brings nothing within it: kept, and each reused
// depth is the corner's distance to the face plane, the narrow phase's own.
TEST_CASE("kept manifold: a box resting on an edge on a box's face is kept, its reused depths the narrow phase's",
          "[kept_manifold]") {
  const BoxOverSlab scene;
  const auto& [base_shape, top_shape, base, top, pose_a] = scene;
  const double tilt = 0.3, lift = 0.25 * (std::cos(tilt) + std::sin(tilt));
  const Eigen::Isometry3d built_at = pose({0.1, -0.05, 0.5 + lift - 2e-7}, rotation(tilt, Vector3d::UnitX()));
  const double margin = 1e-3, slack = 1e-4;
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(base, pose_a, top, built_at, margin, cache, m));
  REQUIRE(m.points.size() == 2);
  KeptManifold kept;
  keepManifold(m, true, pose_a, built_at, pose_a.inverse(Eigen::Isometry) * built_at, ReferenceIs::A, &base_shape,
               top_shape, margin, kept);
  REQUIRE(kept.valid);

  const Eigen::Isometry3d moved = pose({0.1 + 3e-5, -0.05 + 2e-5, 0.5 + lift - 6e-7},
                                       rotation(tilt, Vector3d::UnitX()) * rotation(5e-5, Vector3d(0, 1, 0)));
  const double drift = keptDrift(kept, pose_a.inverse(Eigen::Isometry) * moved, top.radius);
  CHECK(drift <= slack);
  CHECK(checkReusedIsFresh(kept, base, pose_a, top, moved, margin) <= 0.5 * drift);
}

// Were the narrow phase to report only the edge a box rests on while its other bottom edge stands
// within the margin above the face (tilted 4e-4 rad: 0.2 mm up, inside the 1 mm margin), a box
// rocked back by a tenth of a milliradian would touch there, where a kept manifold would not
// look: such a manifold is not kept. The narrow phase reports this footprint face on face (four
// points), but a piece of another shape may report one feature with another within the margin.
TEST_CASE("kept manifold: an edge on a face with another corner within the margin above the face is not kept",
          "[kept_manifold]") {
  const BoxOverSlab scene;
  const auto& [base_shape, top_shape, base, top, pose_a] = scene;
  // The manifold of the corners within 1e-6 m of the face plane (z = 0.5), as the narrow phase
  // writes one: normal from the base (A) to the box (B), midpoints, depths, a feature id each.
  auto edgeManifold = [&](const Eigen::Isometry3d& at) {
    ContactManifold m;
    m.normal = Vector3d::UnitZ();
    std::uint32_t feature = 0;
    for (const Vector3d& v : top_shape.vertices) {
      const Vector3d w = at * v;
      if (w.z() > 0.5 + 1e-6) continue;
      ContactPoint p;
      p.depth = 0.5 - w.z();
      p.position = Vector3d(w.x(), w.y(), 0.5 * (0.5 + w.z()));
      p.feature = ++feature;
      m.points.push_back(p);
    }
    return m;
  };
  auto keptAt = [&](double tilt) {
    const double lift = 0.25 * (std::cos(tilt) + std::sin(tilt));
    const Eigen::Isometry3d at = pose({0.1, -0.05, 0.5 + lift - 2e-7}, rotation(tilt, Vector3d::UnitX()));
    const ContactManifold m = edgeManifold(at);
    REQUIRE(m.points.size() == 2);
    KeptManifold kept;
    keepManifold(m, true, pose_a, at, pose_a.inverse(Eigen::Isometry) * at, ReferenceIs::A, &base_shape, top_shape,
                 1e-3, kept);
    return kept.valid;
  };
  CHECK(keptAt(0.3));          // the other bottom edge 0.15 m up
  CHECK(keptAt(3.9e-3));       // 1.95 mm up: beyond the margin
  CHECK_FALSE(keptAt(1.5e-3)); // 0.75 mm up
  CHECK_FALSE(keptAt(4e-4));   // 0.2 mm up
}

// A box standing on one corner (tilted 0.3 rad about two axes) on a box's face: the narrow phase
// reports the corner alone, the rest stands centimetres above: kept, its reused depth exact.
TEST_CASE("kept manifold: a box on a corner on a box's face is kept, its reused depth the narrow phase's",
          "[kept_manifold]") {
  const BoxOverSlab scene;
  const auto& [base_shape, top_shape, base, top, pose_a] = scene;
  const Eigen::Quaterniond corner = rotation(0.3, Vector3d::UnitX()) * rotation(0.3, Vector3d::UnitY());
  double lowest = 0;
  for (const Vector3d& v : top_shape.vertices) lowest = std::min(lowest, (corner * v).z());
  const Eigen::Isometry3d at = pose({0.1, -0.05, 0.5 - lowest - 2e-7}, corner);
  SatCache cache;
  ContactManifold m;
  REQUIRE(collide(base, pose_a, top, at, 1e-3, cache, m));
  REQUIRE(m.points.size() == 1);
  KeptManifold kept;
  keepManifold(m, true, pose_a, at, pose_a.inverse(Eigen::Isometry) * at, ReferenceIs::A, &base_shape, top_shape,
               1e-3, kept);
  REQUIRE(kept.valid);
  const Eigen::Isometry3d moved = pose({0.1 - 2e-5, -0.05 + 3e-5, 0.5 - lowest - 5e-7}, corner * rotation(4e-5, Vector3d(1, 1, 0)));
  CHECK(keptDrift(kept, pose_a.inverse(Eigen::Isometry) * moved, top.radius) <= 1e-4);
  checkReusedIsFresh(kept, base, pose_a, top, moved, 1e-3);
}
