#include <catch2/catch.hpp>
#include <cmath>

#include "bench/bench_scene.h"
#include "bench/metrics.h"

using namespace tumble::bench;

TEST_CASE("piles are laid out as docs/bench/scenes.md says") {
  const BenchScene p100 = makePile(100);
  REQUIRE(p100.bodies.size() == 100);
  REQUIRE(p100.walls.size() == 4);
  // k = min(10, ceil(sqrt(100 / 4))) = 5: layers of 25, the first cube at (-1.9, -1.9, 0.6).
  CHECK(p100.bodies[0].x.isApprox(Eigen::Vector3d(-1.9, -1.9, 0.6)));
  CHECK(p100.bodies[99].x.z() == Approx(0.6 + 0.9 * 3));
  CHECK(p100.duration == 5);
  CHECK(p100.dts == std::vector<double>{1.0 / 240});
  const BenchScene p1000 = makePile(1000);
  CHECK(p1000.bodies.back().x.z() == Approx(0.6 + 0.9 * 9));   // 10 layers of 10 x 10
  for (const BoxBody& b : p1000.bodies) CHECK(std::abs(b.q.norm() - 1) < 1e-12);
  // No box starts inside another or below the floor: the scene begins at rest and apart.
  std::vector<BodyState> at_rest;
  for (const BoxBody& b : p100.bodies) at_rest.push_back({b.x, b.q, b.v, b.w});
  CHECK(scenePenetration(p100, at_rest) == 0);
}

TEST_CASE("every scene id builds, with its own metrics and headline") {
  for (const std::string& id : allSceneIds()) {
    const BenchScene s = makeScene(id, {1.0 / 60});
    CHECK(!s.bodies.empty());
    CHECK(!headlineMetric(s.kind).empty());
  }
  CHECK_THROWS(makeScene("S9", {1.0 / 60}));
}
