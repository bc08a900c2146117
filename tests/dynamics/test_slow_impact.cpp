// A landing edge while the opposite edge rests (impulse_propagation.cpp, settleShortLiftOffs): at
// speed, Newton's law turns the box about the landing edge and lifts the resting one (a rocking
// block); when gravity would bring the lifted edge back within 4 dt (settleRule,
// baraff/impulse_propagation.h) the impact settles and nothing lifts off, so rocking ends instead of
// chattering at the contact tolerance. For the unit cube turning about an edge the lifted edge
// falls back at 3 g / 4 (gravity's moment m g a / 2 over the edge's moment of inertia 2 m a^2 / 3,
// times the arm a): a lift at w / 4 (the test below) is back after 2 (w / 4) / (3 g / 4) = 2 w / 3 g,
// under 4 dt = 16.7 ms (dt = 1/240 s) for a landing slower than 0.245 m/s.
#include <catch2/catch.hpp>

#include "dynamics/contact_detection.h"
#include "dynamics/contact_rows.h"
#include "dynamics/baraff/collisions.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

struct Landing {
  double landing_vn = 0, resting_vn = 0;   // m/s after the impact, on the x > 0 and x < 0 corners
  double energy_before = 0, energy_after = 0;
};

// scenes/rest.json's unit cube flat on the ground, turning about its bottom edge at x = -0.5 so
// that the edge at x = +0.5 comes down at `speed`; e = 0, and mu = 1 so that the landing edge
// does not slip (the no-slip impulse leans at 0.6 of the normal one).
Landing land(double speed) {
  World world = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json")).world;
  for (RigidBody& b : world.bodies) b.friction = 1.0;
  RigidBody& cube = world.bodies[1];
  const Eigen::Vector3d w(0, speed, 0), pivot(-0.5, 0, -0.5);
  const Eigen::Vector3d v = -w.cross(pivot);
  cube.P = cube.mass * v;
  cube.L = cube.inertia_body.cwiseProduct(w);   // body axes = world axes here
  ContactDetector detector(world);
  ContactSettings settings;
  std::vector<Contact> contacts;
  detector.detect(world, settings, contacts);
  REQUIRE(contacts.size() == 4);
  Landing out;
  out.energy_before = cube.kineticEnergy();
  ContactSolveStats stats;
  resolveCollisions(world, contacts, settings, minBounceSpeed(world, settings, 1.0 / 240), 1.0 / 240, stats);
  out.energy_after = cube.kineticEnergy();
  out.landing_vn = -INFINITY;
  out.resting_vn = -INFINITY;
  for (const Contact& c : contacts) {
    double& side = c.point.x() > 0 ? out.landing_vn : out.resting_vn;
    side = std::max(side, normalVelocity(world, c));
  }
  return out;
}

}  // namespace

TEST_CASE("slow impact: a landing edge whose lift-off would be back within 4 dt stops the box, nothing lifts off", "[impulse]") {
  const Landing l = land(0.2);   // the lifted edge would be back after 13.6 ms < 16.7 ms
  INFO("landing edge " << l.landing_vn << " m/s, resting edge " << l.resting_vn << " m/s");
  CHECK(std::abs(l.landing_vn) < 1e-9);
  CHECK(std::abs(l.resting_vn) < 1e-9);
  CHECK(l.energy_after <= l.energy_before);
}

TEST_CASE("slow impact: a fast landing edge still turns the box about it and lifts the resting edge", "[impulse]") {
  const Landing l = land(0.5);   // the lifted edge would be back after 34 ms > 16.7 ms
  INFO("landing edge " << l.landing_vn << " m/s, resting edge " << l.resting_vn << " m/s");
  CHECK(std::abs(l.landing_vn) < 1e-9);
  // Angular momentum about the landing edge is kept (the impulse acts there, and it does not slip):
  // before, the centre moves parallel to its offset from that edge, so L = I_c w; after, the cube
  // turns about it, L = I_edge w'. For a cube I_c = m a^2 / 6 and I_edge = 2 m a^2 / 3: w' = w / 4,
  // and the resting edge, a = 1 m away, lifts at w / 4 = 0.125 m/s.
  CHECK(l.resting_vn == Approx(0.25 * 0.5).epsilon(1e-6));
  CHECK(l.energy_after < l.energy_before);
}
