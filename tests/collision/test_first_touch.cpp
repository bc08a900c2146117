// firstTouch: conservative advancement of two freely moving pieces, against closed forms.
#include <catch2/catch.hpp>

#include "collision/first_touch.h"
#include "collision_checks.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;
using test::pose;

TEST_CASE("first touch: a box falling onto a box touches when its gap closes", "[narrow][first_touch]") {
  const ConvexPiece box = makeBox(Vector3d(0.1, 0.1, 0.1));   // 0.2 m cubes
  const CollisionHull h = makeCollisionHull(box);
  FreeMotion below, above;
  below.pose = pose(Vector3d::Zero());
  above.pose = pose(Vector3d(0.05, 0.03, 0.21));   // 1 cm apart, face over face
  above.velocity = Vector3d(0, 0, -2);
  const FirstTouch t = firstTouch(h, below, h, above, 0.01, 1e-6);
  REQUIRE(t.touches);
  CHECK(t.time == Approx(0.01 / 2).margin(1e-6 / 2));   // gap / speed, within the tolerance's time
  CHECK(t.normal.z() == Approx(1).margin(1e-9));
}

TEST_CASE("first touch: a box falling past another's edge with 0.5 mm to spare never touches it",
          "[narrow][first_touch]") {
  const ConvexPiece box = makeBox(Vector3d(0.1, 0.1, 0.1));   // 0.2 m cubes
  const CollisionHull h = makeCollisionHull(box);
  FreeMotion wall, falling;
  wall.pose = pose(Vector3d::Zero());
  falling.pose = pose(Vector3d(0.2005, 0, 0.202));   // 0.5 mm beside, 2 mm above the top edge
  falling.velocity = Vector3d(0, 0, -1.5);           // falls 6 mm in the horizon
  const FirstTouch t = firstTouch(h, wall, h, falling, 0.004, 1e-6);
  CHECK_FALSE(t.touches);
  // Drifting 1 mm toward the wall on the way down, it meets the wall's side face at t = 2 ms, 1 mm
  // below the top edge.
  falling.velocity.x() = -0.25;
  const FirstTouch drift = firstTouch(h, wall, h, falling, 0.004, 1e-6);
  REQUIRE(drift.touches);
  CHECK(drift.time == Approx(0.0005 / 0.25).margin(1e-5));
  CHECK(drift.normal.x() == Approx(1).margin(1e-6));
}

TEST_CASE("first touch: a spinning bar sweeps onto a block it does not approach", "[narrow][first_touch]") {
  const ConvexPiece bar = makeBox(Vector3d(0.5, 0.025, 0.025)), block = makeBox(Vector3d(0.05, 0.05, 0.05));
  const CollisionHull hb = makeCollisionHull(bar), hk = makeCollisionHull(block);
  FreeMotion spinning, still;
  spinning.pose = pose(Vector3d::Zero());
  spinning.spin = Vector3d(0, 0, 10);            // tip at 0.5 m moves at 5 m/s
  still.pose = pose(Vector3d(0.4, 0.2, 0));       // beside the bar's end, 0.125 m away from its side
  const FirstTouch t = firstTouch(hb, spinning, hk, still, 0.1, 1e-6);   // turns 1 rad: sweeps it
  REQUIRE(t.touches);
  CHECK(t.time > 0);
  CHECK(t.time < 0.1);
}
