// Scene -> World: exact mass properties, bodies placed where the scene says, errors located.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

std::filesystem::path tempDir() {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "tumble_world_builder_test";
  std::filesystem::create_directories(dir);
  return dir;
}

// The message of the scene error buildWorld raises ("" if none; any other exit code fails).
std::string buildFailure(const Scene& scene) {
  try {
    buildWorld(scene);
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a box's mass and inertia follow from its density", "[dynamics]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"shape": "box", "size_m": [1, 2, 3], "density_kg_m3": 500}]})", "b.json");
  BuiltWorld built = buildWorld(s);
  const RigidBody& b = built.world.bodies[0];
  double m = 500 * 6;
  CHECK(b.mass == Approx(m).epsilon(1e-12));
  // m/12 (b^2 + c^2, a^2 + c^2, a^2 + b^2), in ascending order (principal frame convention)
  CHECK(b.inertia_body.x() == Approx(m / 12 * (1 + 4)).epsilon(1e-12));
  CHECK(b.inertia_body.y() == Approx(m / 12 * (1 + 9)).epsilon(1e-12));
  CHECK(b.inertia_body.z() == Approx(m / 12 * (4 + 9)).epsilon(1e-12));
  // The body frame's z axis (largest moment) is the box's x axis.
  CHECK(std::abs(b.rotation().col(2).x()) == Approx(1).epsilon(1e-12));
}

TEST_CASE("mass_kg scales a body's inertia with its mass", "[dynamics]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"shape": "box", "size_m": [1, 1, 1], "mass_kg": 2}]})", "b.json");
  BuiltWorld built = buildWorld(s);
  const RigidBody& b = built.world.bodies[0];
  CHECK(b.mass == Approx(2));
  CHECK(b.inertia_body.x() == Approx(2.0 / 6));
}

TEST_CASE("a mesh body's centre of mass sits where the scene places the mesh", "[dynamics]") {
  std::filesystem::path dir = tempDir();
  // A unit cube whose file origin is at one corner: its centre of mass is (0.5, 0.5, 0.5) in file
  // coordinates, so placed at (10, 0, 0) rotated 90 deg about z it lands at (9.5, 0.5, 0.5).
  std::ofstream(dir / "corner_cube.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                            "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  std::ofstream(dir / "s.json") << R"({"schema_version": 1, "bodies": [
    {"mesh": "corner_cube.obj", "position_m": [10, 0, 0], "rotation_deg": [0, 0, 90]}]})";
  BuiltWorld built = buildWorld(loadScene(dir / "s.json"));
  const RigidBody& b = built.world.bodies[0];
  CHECK((b.x - Eigen::Vector3d(9.5, 0.5, 0.5)).norm() < 1e-12);
  CHECK(b.mass == Approx(1000));
  // The pieces are in the principal frame: their centroid is the origin.
  REQUIRE(b.pieces[0].vertices.size() == 8);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : b.pieces[0].vertices) sum += v;
  CHECK((sum / 8).norm() < 1e-12);
}

TEST_CASE("an unusable mesh is reported at the body's mesh field", "[dynamics]") {
  std::filesystem::path dir = tempDir();
  std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "flat.json") << "{\"schema_version\": 1,\n \"bodies\": [\n  {\"mesh\": \"flat.obj\"}]}";
  try {
    buildWorld(loadScene(dir / "flat.json"));
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("flat.json:3:12: /bodies/0/mesh: "));
    CHECK_THAT(e.what(), Catch::Contains("flat.obj"));
  }
}

TEST_CASE("initial velocities become momenta", "[dynamics]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"shape": "box", "size_m": [1, 0.4, 0.1], "mass_kg": 1, "rotation_deg": [30, 20, 10],
     "velocity_m_s": [1, 2, 3], "angular_velocity_rad_s": [0.3, -0.2, 0.1]}]})", "b.json");
  BuiltWorld built = buildWorld(s);
  const RigidBody& b = built.world.bodies[0];
  CHECK((b.velocity() - Eigen::Vector3d(1, 2, 3)).norm() < 1e-12);
  CHECK((b.angularVelocity() - Eigen::Vector3d(0.3, -0.2, 0.1)).norm() < 1e-12);
}

// Bodies that start inside one another (src/dynamics/start_overlap.h). The limit is the run-time
// penetration limit, half the thinner piece: 0.5 m for unit boxes.
TEST_CASE("a body placed deep inside another is refused at its position, naming both", "[dynamics]") {
  Scene s = parseScene("{\"schema_version\": 1, \"bodies\": [\n"
                       " {\"name\": \"ground\", \"shape\": \"plane\"},\n"
                       " {\"name\": \"a\", \"shape\": \"box\", \"position_m\": [0, 0, 0.5]},\n"
                       " {\"name\": \"b\", \"shape\": \"box\", \"position_m\": [0.1, 0.1, 0.6]}]}",
                       "deep.json");
  CHECK_THAT(buildFailure(s), Catch::StartsWith("deep.json:4:46: /bodies/2/position_m: body \"b\" starts inside "
                                                "body \"a\": they overlap by 0.9 m, more than the 0.5 m"));
}

TEST_CASE("a body placed below the ground is refused at its own position, whatever the order", "[dynamics]") {
  // The ground comes last, but the box is what the scene placed wrongly: the error points at it.
  Scene s = parseScene("{\"schema_version\": 1, \"bodies\": [\n"
                       " {\"name\": \"crate\", \"shape\": \"box\", \"position_m\": [0, 0, -2]},\n"
                       " {\"name\": \"ground\", \"shape\": \"plane\"}]}",
                       "sunk.json");
  CHECK_THAT(buildFailure(s), Catch::StartsWith("sunk.json:2:50: /bodies/0/position_m: body \"crate\" starts "
                                                "inside body \"ground\": they overlap by 2.5 m"));
}

TEST_CASE("a shallow overlap at the start is a warning, and bodies that only touch get none", "[dynamics]") {
  Scene sunk = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "ground", "shape": "plane"},
    {"name": "crate", "shape": "box", "position_m": [0, 0, 0.49]}]})", "shallow.json");
  BuiltWorld built = buildWorld(sunk);
  REQUIRE(built.warnings.size() == 1);
  CHECK(built.warnings[0] == "bodies \"ground\" and \"crate\" start overlapping by 0.01 m; the first steps push them apart, without a push in velocity");
  // What the warning promises, in both contact models: after 0.2 s the crate rests on the ground
  // (within the 1e-6 m contact tolerance) and was never thrown up (the position projection moves
  // positions only; a penalty or Baumgarte push would leave it rising at cm/s).
  for (ContactModel model : {ContactModel::Baraff, ContactModel::TimeStepping}) {
    INFO((model == ContactModel::Baraff ? "baraff" : "time stepping"));
    BuiltWorld fresh = buildWorld(sunk);
    fresh.step.model = model;
    double fastest_up = 0;
    Simulator sim(std::move(fresh.world), {fresh.step, 8, 7});   // 6 frames of 1/30 s
    sim.run([&](int) { fastest_up = std::max(fastest_up, sim.world().bodies[1].velocity().z()); });
    CHECK(sim.world().bodies[1].x.z() == Approx(0.5).margin(2e-6));
    CHECK(fastest_up < 1e-6);
  }

  // Resting exactly on the ground and on each other (a stack as scenes write it): no warning.
  Scene stack = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "ground", "shape": "plane"},
    {"name": "a", "shape": "box", "position_m": [0, 0, 0.5]},
    {"name": "b", "shape": "box", "position_m": [0.2, 0, 1.5]}]})", "stack.json");
  CHECK(buildWorld(stack).warnings.empty());

  // Two static bodies may overlap: nothing moves them, and nothing needs to.
  Scene statics = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "ground", "shape": "plane"},
    {"name": "wall", "shape": "box", "static": true, "position_m": [0, 0, 0]}]})", "statics.json");
  CHECK(buildWorld(statics).warnings.empty());
}

TEST_CASE("a compound dumbbell: two balls on a bar, its mass and inertia the pieces' sum", "[dynamics]") {
  // Balls of radius 0.1 m centred at x = +-0.3, a bar of radius 0.02 m and length 0.4 m along x
  // between them (its ends touch the balls: no overlap, so the union's mass is the sum).
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "dumbbell", "position_m": [0, 0, 1], "density_kg_m3": 1000, "pieces": [
      {"shape": "sphere", "radius_m": 0.1, "position_m": [-0.3, 0, 0]},
      {"shape": "cylinder", "radius_m": 0.02, "height_m": 0.4, "rotation_deg": [0, 90, 0]},
      {"shape": "sphere", "radius_m": 0.1, "position_m": [0.3, 0, 0]}]}]})", "d.json");
  const BuiltWorld built = buildWorld(s);
  const RigidBody& b = built.world.bodies[0];
  const double ball = 1000 * 4.0 / 3.0 * M_PI * 1e-3, bar = 1000 * M_PI * 4e-4 * 0.4;
  CHECK(b.shape == ShapeKind::Compound);
  CHECK(b.pieces.size() == 3);
  CHECK(b.mass == Approx(2 * ball + bar).epsilon(1e-12));
  CHECK((b.x - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12);
  // about the bar's axis, and across it (parallel axes for the balls)
  const double along = 2 * 0.4 * ball * 0.01 + 0.5 * bar * 4e-4;
  const double across = 2 * (0.4 * ball * 0.01 + ball * 0.09) + bar * (3 * 4e-4 + 0.16) / 12;
  Eigen::Vector3d moments = b.inertia_body;
  std::sort(moments.data(), moments.data() + 3);
  CHECK(moments[0] == Approx(along).epsilon(1e-12));
  CHECK(moments[1] == Approx(across).epsilon(1e-12));
  CHECK(moments[2] == Approx(across).epsilon(1e-12));
}

TEST_CASE("a compound body's bad pieces are located", "[scene]") {
  auto failure = [](const char* text) {
    try {
      parseScene(text, "c.json");
    } catch (const Error& e) {
      CHECK(e.code() == ExitCode::BadInput);
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(failure(R"({"schema_version": 1, "bodies": [{"pieces": []}]})"),
             Catch::Contains("/bodies/0/pieces: a compound body needs at least one piece"));
  CHECK_THAT(failure(R"({"schema_version": 1, "bodies": [{"shape": "box", "pieces": [{"shape": "box"}]}]})"),
             Catch::Contains("/bodies/0/pieces: give \"pieces\" (a compound body) or \"shape\", not both"));
  CHECK_THAT(failure(R"({"schema_version": 1, "bodies": [{"pieces": [{"shape": "sphere", "radius_m": -1}]}]})"),
             Catch::Contains("/bodies/0/pieces/0/radius_m: -1 is outside"));
  CHECK_THAT(failure(R"({"schema_version": 1, "bodies": [{"pieces": [{"shape": "plane"}]}]})"),
             Catch::Contains("/bodies/0/pieces/0/shape"));
  CHECK_THAT(failure(R"({"schema_version": 1, "bodies": [{"pieces": [3]}]})"),
             Catch::Contains("/bodies/0/pieces/0: expected an object"));
}
