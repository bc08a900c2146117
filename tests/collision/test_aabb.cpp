#include <catch2/catch.hpp>

#include <random>

#include "collision/aabb.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;
using test::rotation;

TEST_CASE("aabbOf: rotated box, margin", "[aabb]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.25));
  const Aabb b = aabbOf(box, pose({1, 2, 3}, rotation(std::numbers::pi / 4, Vector3d::UnitZ())), 0.1);
  const double r = 0.5 * std::sqrt(2.0) + 0.1;
  CHECK(b.min.isApprox(Vector3d(1 - r, 2 - r, 3 - 0.35), 1e-12));
  CHECK(b.max.isApprox(Vector3d(1 + r, 2 + r, 3 + 0.35), 1e-12));
}

TEST_CASE("overlaps: closed intervals, touching boxes overlap", "[aabb]") {
  const Aabb a{Vector3d(0, 0, 0), Vector3d(1, 1, 1)};
  CHECK(overlaps(a, Aabb{Vector3d(1, 0, 0), Vector3d(2, 1, 1)}));
  CHECK_FALSE(overlaps(a, Aabb{Vector3d(1 + 1e-12, 0, 0), Vector3d(2, 1, 1)}));
  CHECK_FALSE(overlaps(a, Aabb{Vector3d(0, 0, -2), Vector3d(1, 1, -0.5)}));
}

// The path the proof in aabb.cpp assumes: straight translation, rotation about one axis at a
// uniform rate. Every vertex at every sampled instant must be inside the swept box.
TEST_CASE("sweptAabb: holds the piece along the whole step", "[aabb]") {
  const ConvexPiece box = makeBox(Vector3d(1.0, 0.2, 0.1));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3d x0(u(rng), u(rng), u(rng)), x1 = x0 + 0.3 * Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Quaterniond q0 = Eigen::Quaterniond::UnitRandom();
    const Vector3d axis = Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double turn = 3.0 * std::abs(u(rng));  // up to 3 rad in one step
    const auto pose_at = [&](double s) { return pose((1 - s) * x0 + s * x1, rotation(s * turn, axis) * q0); };
    const Aabb swept = sweptAabb(box, pose_at(0), pose_at(1), turn, 0);
    for (int k = 0; k <= 64; ++k) {
      const Aabb at = aabbOf(box, pose_at(k / 64.0), 0);
      REQUIRE((at.min.array() >= swept.min.array() - 1e-12).all());
      REQUIRE((at.max.array() <= swept.max.array() + 1e-12).all());
    }
  }
}

TEST_CASE("rotationAngle: angle of the relative rotation", "[aabb]") {
  const auto q = Eigen::Quaterniond::UnitRandom();
  CHECK(rotationAngle(pose({0, 0, 0}, q), pose({1, 0, 0}, rotation(0.3, Vector3d(1, 2, 3)) * q)) ==
        Approx(0.3).epsilon(1e-9));
}
