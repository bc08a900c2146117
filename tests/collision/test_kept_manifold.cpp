// A kept manifold reused at a moved pose against the narrow phase run afresh there: exact for a
// box's corners on a face, and its drift bound never below how far a corner really moved.
#include <catch2/catch.hpp>

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

}  // namespace

TEST_CASE("kept manifold: a box resting on a box, moved within the slack, gives the narrow phase's depths",
          "[kept_manifold]") {
  const ConvexPiece base_shape = makeBox(Vector3d(1.0, 1.0, 0.25));
  const ConvexPiece top_shape = makeBox(Vector3d(0.25, 0.25, 0.25));
  const CollisionHull base = makeCollisionHull(base_shape), top = makeCollisionHull(top_shape);
  const Eigen::Isometry3d pose_a = pose({0, 0, 0.25});
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

  ContactManifold reused, fresh;
  REQUIRE(reuseManifold(kept, pose_a, moved, ReferenceIs::A, margin, reused));
  SatCache fresh_cache;
  REQUIRE(collide(base, pose_a, top, moved, margin, fresh_cache, fresh));
  REQUIRE(reused.points.size() == fresh.points.size());
  CHECK((reused.normal - fresh.normal).norm() < 1e-12);
  for (const ContactPoint& p : reused.points) {
    const ContactPoint* q = withFeature(fresh, p.feature);
    REQUIRE(q != nullptr);
    // Rounding of the transforms only: 1e-12 m on a metre-sized pair.
    CHECK(std::abs(p.depth - q->depth) < 1e-12);
    // The point on the base's face stays where the corner was: the midpoint lags by half the slide.
    CHECK((p.position - q->position).norm() <= 0.5 * drift);
  }
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
