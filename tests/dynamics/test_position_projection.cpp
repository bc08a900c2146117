// Drift projection by pair (position_projection.h): a face flush within the tolerance is moved
// straight out to half the tolerance deep; a landing edge is lifted by turning the body about the
// edge it rests on (held at half the tolerance), not by lifting the whole body.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "dynamics/contact_detection.h"
#include "dynamics/position_projection.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

constexpr double kTol = 1e-6;

// scenes/rest.json: a unit cube (1 kg) on the ground; the cube is body 1.
World restWorld() {
  return buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json")).world;
}

std::vector<Contact> contactsOf(const World& world) {
  ContactDetector detector(world);
  std::vector<Contact> out;
  ContactSettings settings;
  detector.detect(world, settings, out);
  return out;
}

std::vector<const Contact*> pointers(const std::vector<Contact>& contacts) {
  std::vector<const Contact*> out;
  for (const Contact& c : contacts) out.push_back(&c);
  return out;
}

// Lowest z of the cube's corners on the side x < 0 and on the side x > 0.
std::pair<double, double> lowestBySide(const RigidBody& cube) {
  double left = INFINITY, right = INFINITY;
  for (const Eigen::Vector3d& v : cube.pieces[0].vertices) {
    double& side = v.x() < 0 ? left : right;
    side = std::min(side, (cube.x + cube.rotation() * v).z());
  }
  return {left, right};
}

}  // namespace

TEST_CASE("projection: a face sunk evenly is lifted straight up to half the tolerance", "[projection]") {
  // (all four corners equally deep: flush, moved straight out, never turned)
  World world = restWorld();
  RigidBody& cube = world.bodies[1];
  cube.x.z() = 0.5 - 1e-4;   // all four corners 0.1 mm deep
  const Eigen::Quaterniond q0 = cube.q;
  std::vector<Contact> contacts = contactsOf(world);
  REQUIRE(contacts.size() == 4);
  REQUIRE(projectPair(world, pointers(contacts), kTol, extentsOf(world)));
  auto [left, right] = lowestBySide(cube);
  INFO("lowest corners: " << left << ", " << right);
  CHECK(left == Approx(-0.5 * kTol).margin(1e-12));
  CHECK(right == Approx(-0.5 * kTol).margin(1e-12));
  CHECK(q0.angularDistance(cube.q) < 1e-12);
  CHECK(cube.x.head<2>().norm() < 1e-12);
}

TEST_CASE("projection: a landing edge is lifted by turning about the resting edge", "[projection]") {
  World world = restWorld();
  RigidBody& cube = world.bodies[1];
  // Tilted about y so that the edge at x = +0.5 is 0.1 mm deeper than the one at x = -0.5, which
  // touches the ground exactly.
  const double angle = std::asin(1e-4);
  cube.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()));
  cube.x.z() -= lowestBySide(cube).first;   // the resting edge on z = 0
  const double z0 = cube.x.z();
  std::vector<Contact> contacts = contactsOf(world);
  REQUIRE(contacts.size() == 4);
  REQUIRE(projectPair(world, pointers(contacts), kTol, extentsOf(world)));
  auto [left, right] = lowestBySide(cube);
  INFO("resting edge " << left << " m, landing edge " << right << " m, centre rose " << cube.x.z() - z0 << " m");
  // The turn is solved to first order in its angle (1e-4 rad): second-order terms are ~1e-8 m.
  CHECK(left == Approx(-0.5 * kTol).margin(1e-8));    // settled by half the tolerance, no more
  CHECK(right == Approx(-0.5 * kTol).margin(1e-8));   // lifted to half the tolerance
  // Turning about the resting edge lifts the centre by about half of what the landing edge rose
  // (the old push lifted it, and the resting edge, by all of it: 1e-4 m).
  CHECK(cube.x.z() - z0 == Approx(0.5 * (1e-4 - 0.5 * kTol)).epsilon(0.05));
}

TEST_CASE("projection: nothing deeper than the tolerance, nothing moves", "[projection]") {
  World world = restWorld();
  world.bodies[1].x.z() = 0.5 - 0.5 * kTol;
  const World before = world;
  std::vector<Contact> contacts = contactsOf(world);
  CHECK_FALSE(projectPair(world, pointers(contacts), kTol, extentsOf(world)));
  CHECK(world.bodies[1].x == before.bodies[1].x);
}
