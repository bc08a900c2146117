// The collision stage repeats until no touching contact approaches (baraff/collisions.cpp): an
// impact that drives a body onto a touching neighbour it was separating from when the impact began
// is followed, in the same stage, by that neighbour's impact. Left to the next sub-step, which
// takes a touching pair that is not lifting off for one at rest, two 100 g plates chattering
// between two blocks went 1.2-1.8 mm into the block below within a sub-step.
#include <catch2/catch.hpp>

#include "dynamics/baraff/collisions.h"
#include "dynamics/contact_detection.h"
#include "dynamics/contact_rows.h"
#include "scene/scene_loader.h"
#include "scene/world_builder.h"

using namespace tumble;

TEST_CASE("collisions: a block landing on a plate that is lifting off the block below leaves no touching contact approaching",
          "[contact][impulse]") {
  // scenes/hard/pinched_plate.json, every gap closed: a 64 kg block on the ground, a 2 kg plate on
  // it lifting off at 0.05 m/s, a second 64 kg block landing on the plate at 0.3 m/s; e = 0, so the
  // landing lifts nothing off and no neighbour is taken in for turning a lift-off back.
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/hard/pinched_plate.json");
  for (auto& b : scene.bodies) b.restitution = 0;
  World world = buildWorld(scene).world;
  for (RigidBody& b : world.bodies) {
    if (b.name == "low") b.x.z() = 0.2;
    if (b.name == "plate") {
      b.x.z() = 0.402;
      b.P = b.mass * Eigen::Vector3d(0, 0, 0.05);
    }
    if (b.name == "top") {
      b.x.z() = 0.604;
      b.P = b.mass * Eigen::Vector3d(0, 0, -0.3);
    }
  }
  ContactSettings settings;
  std::vector<Contact> contacts;
  ContactDetector(world).detect(world, settings, contacts);
  REQUIRE(contacts.size() >= 12);   // ground-block, block-plate, plate-block: four corners or more each
  const double dt = 1.0 / 240;
  ContactSolveStats stats;
  REQUIRE(resolveCollisions(world, contacts, settings, minBounceSpeed(world, settings, dt), dt, stats));
  double slowest = 0;   // the most negative normal speed of a touching contact (m/s)
  for (const Contact& c : contacts)
    if (c.depth >= -settings.tolerance_m) slowest = std::min(slowest, normalVelocity(world, c));
  INFO("fastest approach left: " << slowest << " m/s");
  CHECK(slowest >= -settings.resting_speed_m_s);
}
