// The scene loader: every bad input gets an error naming the file, line, column and JSON pointer,
// with the documented exit code; good input gets the documented defaults and conventions.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

using namespace tumble;

namespace {

// Parses `text` as if it were the file scenes/test.json; returns the error message ("" if none)
// and its exit code.
struct Outcome {
  std::string message;
  ExitCode code = ExitCode::Ok;
};

Outcome tryParse(const std::string& text) {
  try {
    parseScene(text, "scenes/test.json");
  } catch (const Error& e) {
    return {e.what(), e.code()};
  }
  return {};
}

const char* kMinimal = R"({
  "schema_version": 1,
  "bodies": [ { "name": "cube", "shape": "box" } ]
})";

}  // namespace

TEST_CASE("a minimal scene loads with the documented defaults", "[scene]") {
  Scene s = parseScene(kMinimal, "scenes/test.json");
  REQUIRE(s.bodies.size() == 1);
  CHECK(s.name == "test");
  CHECK(s.bodies[0].shape == ShapeKind::Box);
  CHECK(s.bodies[0].density_kg_m3 == 1000);
  CHECK(s.simulation.gravity_m_s2.z() == -9.81);
  CHECK(s.render.fps == 30);
  CHECK(s.simulation.steps_per_frame == 8);
  CHECK(s.simulation.step.dt == 1.0 / 30 / 8);
  CHECK(s.lighting.directional.size() == 1);
}

TEST_CASE("comments are allowed", "[scene]") {
  Scene s = parseScene(R"({
    // a line comment
    "schema_version": 1, /* a block comment */
    "bodies": [ { "shape": "sphere", "radius_m": 0.25 } ]
  })", "scenes/test.json");
  CHECK(s.bodies[0].radius_m == 0.25);
  CHECK(s.bodies[0].name == "body_0");
}

TEST_CASE("a capsule: radius, the straight part's length, how finely it is drawn", "[scene]") {
  const Scene c = parseScene(R"({"schema_version": 1,
    "bodies": [ { "shape": "capsule", "radius_m": 0.1, "length_m": 0.4, "subdivisions": 4 } ]})", "scenes/test.json");
  CHECK(c.bodies[0].shape == ShapeKind::Capsule);
  CHECK(c.bodies[0].radius_m == 0.1);
  CHECK(c.bodies[0].capsule_length_m == 0.4);
  CHECK(c.bodies[0].subdivisions == 4);
}

TEST_CASE("rotation_deg uses extrinsic XYZ (Blender's XYZ Euler)", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"shape": "box", "rotation_deg": [90, 0, 90]} ]})", "scenes/test.json");
  // About world x by 90 deg (y -> z), then about world z by 90 deg (x -> y): the body's y axis
  // first goes to z and stays there; the body's x axis goes to y.
  Eigen::Matrix3d R = s.bodies[0].orientation.toRotationMatrix();
  CHECK((R * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm() < 1e-12);
  CHECK((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm() < 1e-12);
}

TEST_CASE("quat_wxyz is normalised and w comes first", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"shape": "box", "quat_wxyz": [2, 0, 0, 2]} ]})", "scenes/test.json");
  Eigen::Quaterniond q = s.bodies[0].orientation;
  CHECK(q.w() == Approx(std::sqrt(0.5)));
  CHECK(q.z() == Approx(std::sqrt(0.5)));
}

TEST_CASE("dt_s must divide the frame interval, and the exact step is interval / steps", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "simulation": {"dt_s": 0.0041667},
    "render": {"fps": 24}, "bodies": [{"shape": "box"}]})", "scenes/test.json");
  CHECK(s.simulation.steps_per_frame == 10);
  CHECK(s.simulation.step.dt == 1.0 / 24 / 10);
  Outcome bad = tryParse(R"({"schema_version": 1, "simulation": {"dt_s": 0.013},
    "bodies": [{"shape": "box"}]})");
  CHECK(bad.code == ExitCode::BadInput);
  CHECK_THAT(bad.message, Catch::Contains("/simulation/dt_s") && Catch::Contains("does not divide"));
}

TEST_CASE("the contact time search and tolerance are scene settings", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "simulation": {"time_of_impact": "regula_falsi",
    "contact_tolerance_m": 1e-5}, "bodies": [{"shape": "box"}]})", "scenes/test.json");
  CHECK(s.simulation.step.contact.regula_falsi);
  CHECK(s.simulation.step.contact.tolerance_m == 1e-5);
  CHECK_FALSE(parseScene(kMinimal, "scenes/test.json").simulation.step.contact.regula_falsi);
}

TEST_CASE("duration_s sets the frame count so that the last frame shows the duration", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "render": {"fps": 25, "duration_s": 2},
    "bodies": [{"shape": "box"}]})", "scenes/test.json");
  CHECK(s.render.frames == 51);   // t = 0, 0.04, ..., 2 s
  CHECK(durationOfFrames(s.render.frames, s.render.fps) == 2.0);
  setDuration(s, 1);
  CHECK(s.render.frames == 26);
}

TEST_CASE("each bad input names file, line, column and field", "[scene]") {
  struct Case {
    const char* what;
    const char* text;
    const char* expected;   // a substring of the message
    ExitCode code;
  };
  const Case cases[] = {
      {"syntax error", "{\n  \"schema_version\": 1,\n  \"bodies\": [ }\n}", "scenes/test.json:3:", ExitCode::BadInput},
      {"trailing comma", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\"},]}", "invalid JSON", ExitCode::BadInput},
      {"unknown key with a suggestion",
       "{\"schema_version\": 1,\n \"bodies\": [{\"shape\": \"box\",\n   \"restitusion\": 0.3}]}",
       "scenes/test.json:3:4: /bodies/0/restitusion: unknown field \"restitusion\"; did you mean \"restitution\"?",
       ExitCode::BadInput},
      {"out of range",
       "{\"schema_version\": 1,\n \"bodies\": [{\"shape\": \"box\"},\n  {\"shape\": \"box\", \"restitution\": 1.5}]}",
       "scenes/test.json:3:35: /bodies/1/restitution: 1.5 is outside [0, 1]", ExitCode::BadInput},
      {"wrong type", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"mass_kg\": \"heavy\"}]}",
       "/bodies/0/mass_kg: expected a number, got a string (\"heavy\")", ExitCode::BadInput},
      {"negative mass", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"mass_kg\": -1}]}",
       "/bodies/0/mass_kg: -1 is outside (0, 1000000000000]", ExitCode::BadInput},
      {"zero mass", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"mass_kg\": 0}]}",
       "/bodies/0/mass_kg: 0 is outside (0, 1000000000000]", ExitCode::BadInput},
      {"infinite number", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"friction\": 1e999}]}",
       "scenes/test.json:1:63: invalid JSON: number overflow", ExitCode::BadInput},
      {"NaN as a string", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"position_m\": [0, \"NaN\", 0]}]}",
       "/bodies/0/position_m/1: expected a number", ExitCode::BadInput},
      {"missing bodies", "{\"schema_version\": 1}", "missing required field \"bodies\"", ExitCode::BadInput},
      {"misspelled bodies", "{\"schema_version\": 1, \"bodys\": []}", "did you mean \"bodies\"?", ExitCode::BadInput},
      {"empty bodies", "{\"schema_version\": 1, \"bodies\": []}", "/bodies: the scene has no bodies", ExitCode::BadInput},
      {"no schema version", "{\"bodies\": [{\"shape\": \"box\"}]}", "schema_version", ExitCode::BadInput},
      {"future schema", "{\"schema_version\": 2, \"bodies\": [{\"shape\": \"box\"}]}", "reads schema version 1", ExitCode::BadInput},
      {"duplicate names", "{\"schema_version\": 1, \"bodies\": [{\"name\": \"a\", \"shape\": \"box\"}, {\"name\": \"a\", \"shape\": \"box\"}]}",
       "/bodies/1/name: another body is already named \"a\"", ExitCode::BadInput},
      {"unknown shape", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"boxx\"}]}", "did you mean \"box\"?", ExitCode::BadInput},
      {"zero radius", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"sphere\", \"radius_m\": 0}]}",
       "scenes/test.json:1:66: /bodies/0/radius_m: 0 is outside [1e-06, 1000000]", ExitCode::BadInput},
      {"negative capsule radius", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"capsule\", \"radius_m\": -0.1}]}",
       "/bodies/0/radius_m: -0.1 is outside [1e-06, 1000000]", ExitCode::BadInput},
      {"capsule shorter than zero", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"capsule\", \"length_m\": -1}]}",
       "/bodies/0/length_m: -1 is outside [0, 1000000]", ExitCode::BadInput},
      {"a flat cone", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"cone\", \"height_m\": 0}]}",
       "/bodies/0/height_m: 0 is outside [1e-06, 1000000]", ExitCode::BadInput},
      {"a cylinder of no radius", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"cylinder\", \"radius_m\": 0}]}",
       "/bodies/0/radius_m: 0 is outside [1e-06, 1000000]", ExitCode::BadInput},
      {"a tube with no wall", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"tube\", \"radius_m\": 0.1, \"inner_radius_m\": 0.1}]}",
       "/bodies/0/inner_radius_m: a tube's bore (0.1 m) must be narrower than its radius (0.1 m)", ExitCode::BadInput},
      {"a box's size on a capsule", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"capsule\", \"size_m\": [1, 1, 1]}]}",
       "/bodies/0/size_m: unknown field", ExitCode::BadInput},
      {"neither mesh nor shape", "{\"schema_version\": 1, \"bodies\": [{\"name\": \"x\"}]}", "needs \"mesh\"", ExitCode::BadInput},
      {"missing mesh file", "{\"schema_version\": 1, \"bodies\": [{\"mesh\": \"no/such.obj\"}]}",
       "/bodies/0/mesh: cannot read mesh file", ExitCode::MissingInput},
      {"moving plane", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"plane\", \"static\": false}]}",
       "/bodies/0/static", ExitCode::BadInput},
      {"static with velocity", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"static\": true, \"velocity_m_s\": [1, 0, 0]}]}",
       "static body cannot have a velocity", ExitCode::BadInput},
      {"huge frame", "{\"schema_version\": 1, \"render\": {\"width\": 100000}, \"bodies\": [{\"shape\": \"box\"}]}",
       "/render/width: 100000 is outside [16, 8192]", ExitCode::BadInput},
      {"a billion frames", "{\"schema_version\": 1, \"render\": {\"frames\": 1000000000}, \"bodies\": [{\"shape\": \"box\"}]}",
       "/render/frames", ExitCode::BadInput},
      {"zero fps", "{\"schema_version\": 1, \"render\": {\"fps\": 0}, \"bodies\": [{\"shape\": \"box\"}]}",
       "/render/fps: 0 is outside [1, 1000]", ExitCode::BadInput},
      {"zero dt", "{\"schema_version\": 1, \"simulation\": {\"dt_s\": 0}, \"bodies\": [{\"shape\": \"box\"}]}",
       "/simulation/dt_s: 0 is outside (0, 0.1]", ExitCode::BadInput},
      {"zero quaternion", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"quat_wxyz\": [0, 0, 0, 0]}]}",
       "cannot be zero", ExitCode::BadInput},
      {"bad colour", "{\"schema_version\": 1, \"bodies\": [{\"shape\": \"box\", \"color\": \"red\"}]}",
       "/bodies/0/color: expected \"#rrggbb\"", ExitCode::BadInput},
      {"top level not an object", "[1, 2]", "expected an object", ExitCode::BadInput},
      {"camera looking at itself", "{\"schema_version\": 1, \"camera\": {\"position_m\": [1,1,1], \"look_at_m\": [1,1,1]}, \"bodies\": [{\"shape\": \"box\"}]}",
       "/camera/look_at_m", ExitCode::BadInput},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    Outcome out = tryParse(c.text);
    CHECK(out.code == c.code);
    CHECK_THAT(out.message, Catch::Contains(c.expected));
  }
}

TEST_CASE("a missing or unreadable scene file is MissingInput", "[scene]") {
  try {
    loadScene("no/such/scene.json");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::MissingInput);
    CHECK_THAT(e.what(), Catch::Contains("no/such/scene.json"));
  }
}

TEST_CASE("mesh paths are relative to the scene file", "[scene]") {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "tumble_scene_test";
  std::filesystem::create_directories(dir / "meshes");
  std::ofstream(dir / "meshes" / "m.obj") << "v 0 0 0\n";
  std::ofstream(dir / "s.json") << R"({"schema_version": 1, "bodies": [{"mesh": "meshes/m.obj"}]})";
  Scene s = loadScene(dir / "s.json");
  CHECK(s.bodies[0].mesh == (dir / "meshes" / "m.obj").lexically_normal());
  CHECK(s.bodies[0].mesh_location.line == 1);
  std::filesystem::remove_all(dir);
}
