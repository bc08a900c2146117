// "joints" through the real loader: what a good scene reads and the world it builds (anchors and
// axes in the bodies' own frames), and the errors the hand-written bad scenes in bad/ do not cover.
#include <catch2/catch.hpp>

#include <cmath>

#include "base/error.h"
#include "dynamics/joints/joint.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

const char* kArm = R"({ "schema_version": 1,
  "bodies": [ { "name": "post", "shape": "box", "size_m": [0.1, 0.1, 1], "position_m": [0, 0.2, 0.5], "static": true },
              { "name": "arm", "shape": "box", "size_m": [0.6, 0.04, 0.04], "position_m": [0.3, 0, 1],
                "rotation_deg": [0, 0, 10] } ],
  "joints": [ { "name": "shoulder", "type": "hinge", "bodies": ["post", "arm"], "anchor_m": [0, 0, 1],
                "axis": [0, 0, 2], "limits_deg": [-45, 90],
                "motor": { "target_deg": 30, "kp": 20, "kd": 1.5 } },
              { "type": "ball", "bodies": ["world", "arm"], "anchor_m": [0.6, 0, 1] } ] })";

std::string errorOf(const std::string& text) {
  try {
    buildWorld(parseScene(text, "scenes/test.json"));
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("joints load with their bodies, anchor, unit axis, limits and motor in radians", "[scene][joints]") {
  const Scene s = parseScene(kArm, "scenes/test.json");
  REQUIRE(s.joints.size() == 2);
  const JointSpec& j = s.joints[0];
  CHECK(j.name == "shoulder");
  CHECK(j.type == JointType::Hinge);
  CHECK(j.body_a == "post");
  CHECK(j.body_b == "arm");
  CHECK(j.axis.isApprox(Eigen::Vector3d::UnitZ()));
  REQUIRE(j.limits_deg);
  CHECK((*j.limits_deg)[0] == -45);
  CHECK(j.motor.kind == JointMotor::Kind::Position);
  CHECK(j.motor.target_rad == Approx(M_PI / 6));
  CHECK(s.joints[1].body_a == "world");
}

TEST_CASE("the world keeps each joint's anchor and axis in its bodies' frames", "[scene][joints]") {
  const World world = buildWorld(parseScene(kArm, "scenes/test.json")).world;
  REQUIRE(world.joints.size() == 2);
  const Joint& hinge = world.joints[0];
  CHECK(hinge.a == 0);
  CHECK(hinge.b == 1);
  CHECK(hinge.limited);
  CHECK(hinge.upper_rad == Approx(M_PI / 2));
  const RigidBody& arm = world.bodies[1];
  // Body frame: origin at the centre of mass, principal axes; back in the world it is the anchor.
  CHECK((arm.x + arm.rotation() * hinge.anchor_b).isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  CHECK((arm.rotation() * hinge.axis_b).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  CHECK(anchorGap(world, hinge) < 1e-12);
  CHECK(hingeAngle(world, hinge) == Approx(0).margin(1e-12));
  CHECK(world.joints[1].a == -1);                         // the world
  CHECK(world.joints[1].anchor_a.isApprox(Eigen::Vector3d(0.6, 0, 1)));
}

TEST_CASE("joint errors name the field: a body called world, a joint that holds nothing, a motor without kp", "[scene][joints]") {
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "name": "world", "shape": "box" } ],
  "joints": [ { "type": "ball", "bodies": ["world", "world"], "anchor_m": [0, 0, 1] } ] })")
            .find("scenes/test.json:3:13: /joints: a body is named \"world\"") == 0);
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "name": "ground", "shape": "plane" }, { "name": "box", "shape": "box", "position_m": [0, 0, 2] } ],
  "joints": [ { "type": "fixed", "bodies": ["world", "ground"], "anchor_m": [0, 0, 0] } ] })")
            .find("/joints/0/bodies: neither \"world\" nor \"ground\" can move") != std::string::npos);
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "name": "box", "shape": "box", "position_m": [0, 0, 2] } ],
  "joints": [ { "type": "hinge", "bodies": ["world", "box"], "anchor_m": [0, 0, 2.5], "axis": [1, 0, 0],
                "motor": { "target_deg": 10 } } ] })")
            .find("/joints/0/motor: a PD motor needs \"kp\"") != std::string::npos);
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "name": "box", "shape": "box", "position_m": [0, 0, 2] } ],
  "joints": [ { "type": "hinge", "bodies": ["world", "box"], "anchor_m": [0, 0, 2.5], "axis": [1, 0, 0],
                "limits_deg": [10, 20] } ] })")
            .find("/joints/0/limits_deg: the hinge starts at 0 deg, outside [10, 20]") != std::string::npos);
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "name": "box", "shape": "box", "position_m": [0, 0, 2] } ],
  "joints": [ { "name": "j", "type": "ball", "bodies": ["world", "box"], "anchor_m": [0, 0, 2.5] },
              { "name": "j", "type": "ball", "bodies": ["world", "box"], "anchor_m": [0, 0, 1.5] } ] })")
            .find("/joints/1/name: another joint is already named \"j\"") != std::string::npos);
}

TEST_CASE("a --contact-model penalty on a scene with joints is a usage error", "[scene][joints]") {
  Scene s = parseScene(kArm, "scenes/test.json");
  try {
    setContactModel(s, ContactModel::Penalty, "--contact-model");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::Usage);
    CHECK_THAT(e.what(), Catch::StartsWith("--contact-model: the penalty contact model does not simulate joints, "
                                           "and the scene has 2 (\"joints\")"));
  }
  setContactModel(s, ContactModel::TimeStepping, "--contact-model");
  CHECK(s.simulation.step.model == ContactModel::TimeStepping);
}
