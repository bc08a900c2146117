// Ten unit cubes stacked on the ground (benchmark S4), for the full 10 s of its criterion.
#include <catch2/catch.hpp>

#include "contact_scene_runner.h"

using namespace tumble;

TEST_CASE("stack of ten stands still", "[contact]") {
  auto run = test::runScene("stack10", 10);
  const BodySample& top0 = run.trajectory.frames.front()[10];
  const BodySample& top1 = run.trajectory.frames.back()[10];
  CHECK((top1.x - top0.x).head<2>().norm() < 1e-4);
  CHECK(std::abs(top1.x.z() - top0.x.z()) < 1e-4);
  CHECK(run.max_penetration < 1e-6);
}
