// render --dry-run through the real command line: it prints the settings after the command
// line's overrides, each frame's simulated instant and file, and writes nothing.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {
const std::string kSource = TUMBLE_SOURCE_DIR;
}

TEST_CASE("render --dry-run prints each frame's instant and file and writes nothing", "[cli][dry-run]") {
  const fs::path dir = fs::temp_directory_path() / "tumble_dry_run";
  fs::remove_all(dir);
  auto r = runTumble("render " + kSource + "/tests/scenes/cameras.json --camera follow --fps 20 --size 320x240 "
                     "--frames 1,5,19 --dry-run -o " + (dir / "f_####.png").string());
  CHECK(r.exit_code == 0);
  // The scene's 10 frames at 10 fps span 0.9 s; at 20 fps so do 19.
  CHECK_THAT(r.output, Catch::Contains("320x240, 20 fps, 19 frames") && Catch::Contains("follow (--camera follow)"));
  CHECK_THAT(r.output, Catch::Contains("t = 0.2          " + (dir / "f_0005.png").string()));
  CHECK_THAT(r.output, Catch::Contains("t = 0.9          " + (dir / "f_0019.png").string()));
  CHECK_FALSE(fs::exists(dir));
  // Mistakes are found as a render would find them, with the same codes.
  CHECK(runTumble("render " + kSource + "/tests/scenes/cameras.json --camera nope --dry-run").exit_code == 64);
  CHECK(runTumble("render " + kSource + "/tests/scene/bad/camera_follow_no_body.json --dry-run").exit_code == 65);
}

TEST_CASE("a 2 s scene at 30 fps reaches t = 2 s: 61 frames, the last at 2 s", "[cli][dry-run]") {
  const fs::path dir = fs::temp_directory_path() / "tumble_duration";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "two_seconds.json";
  std::ofstream(scene) << R"({ "schema_version": 1, "render": { "fps": 30, "duration_s": 2 },
    "bodies": [ { "name": "ground", "shape": "plane" },
                { "name": "box", "shape": "box", "position_m": [0, 0, 3] } ] })";
  auto dry = runTumble("render " + scene.string() + " --dry-run");
  CHECK_THAT(dry.output, Catch::Contains("61 frames in the clip") && Catch::Contains("61  t = 2\n"));
  auto sim = runTumble("simulate " + scene.string() + " -q --trajectory -");
  REQUIRE(sim.exit_code == 0);
  CHECK_THAT(sim.output, Catch::Contains("\n2,box,"));          // the last row's instant
  CHECK_THAT(sim.output, Catch::Contains("\n1.9666666666666666,box,") || Catch::Contains("\n1.966666666666667,box,"));
  // --duration means the same.
  CHECK_THAT(runTumble("render " + scene.string() + " --duration 1 --dry-run").output, Catch::Contains("31  t = 1\n"));
}
