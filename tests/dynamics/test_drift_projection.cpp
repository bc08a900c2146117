// The time-stepping model's drift projection (time_stepping/drift_projection.h), in its deep passes
// (a speed setting projects only with those): a pair stacked along gravity is pushed apart by
// moving its upper body alone, unless only the lower one can move.
#include <catch2/catch.hpp>

#include <string>

#include "dynamics/contact_detection.h"
#include "dynamics/time_stepping/drift_projection.h"
#include "scene/scene_loader.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

constexpr double kTol = 1e-6;   // the contact tolerance; the deep passes push what is 100 times deeper

// A 1 m ground cube and, per `upper`, the body 1 m above it, overlapping it by 5 mm.
World stackedWorld(const std::string& lower, const std::string& upper) {
  const std::string text = R"({ "schema_version": 1, "render": { "fps": 30, "duration_s": 1 },
    "camera": { "position_m": [3, -4, 2], "look_at_m": [0, 0, 0.5], "fov_y_deg": 40 },
    "bodies": [
      { "name": "ground", "shape": "plane" },
      { "name": "lower", "shape": "box", "size_m": [1, 1, 1], "mass_kg": 1, "position_m": [0, 0, 0.5])" +
                           lower + R"( },
      { "name": "upper", "shape": "box", "size_m": [1, 1, 1], "mass_kg": 1, "position_m": [0, 0, 1.495])" +
                           upper + R"( } ] })";
  return buildWorld(parseScene(text, "stacked.json")).world;
}

std::vector<Contact> contactsOf(const World& world) {
  ContactDetector detector(world);
  std::vector<Contact> out;
  detector.detect(world, ContactSettings{}, out);
  return out;
}

}  // namespace

TEST_CASE("drift projection, deep passes: a cube sunk into the cube below is lifted alone", "[projection][time_stepping]") {
  World world = stackedWorld("", "");
  std::vector<Contact> contacts = contactsOf(world);
  DriftProjection projection;
  REQUIRE(projection.project(world, contacts, kTol, true) > 0);
  // Pushed apart by their masses, the lower cube would sink 2.5 mm into the ground.
  CHECK(world.bodies[1].x.z() == 0.5);
  CHECK(world.bodies[2].x.z() == Approx(1.5 - 0.5 * kTol).margin(1e-9));
  for (const Contact& c : contacts) CHECK(c.depth <= kTol);
}

TEST_CASE("drift projection, deep passes: a cube sunk up into a fixed slab above is pushed down out of it",
          "[projection][time_stepping]") {
  // The upper body cannot move: holding the lower one too would leave the pair as deep as it was.
  World world = stackedWorld("", R"(, "static": true)");
  world.bodies[1].x.z() = 0.6;     // lifted off the ground: only the slab above touches it,
  world.bodies[2].x.z() = 1.595;   // 5 mm into it
  std::vector<Contact> contacts = contactsOf(world);
  DriftProjection projection;
  REQUIRE(projection.project(world, contacts, kTol, true) > 0);
  CHECK(world.bodies[1].x.z() == Approx(0.6 - 0.005 + 0.5 * kTol).margin(1e-9));
  CHECK(world.bodies[2].x.z() == 1.595);
  for (const Contact& c : contacts) CHECK(c.depth <= kTol);
}
