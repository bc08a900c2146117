// render --dry-run through the real command line: it prints the settings after the command
// line's overrides, each frame's simulated instant and file, and writes nothing.
#include <catch2/catch.hpp>

#include <filesystem>

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
                     "--frames 1,5,20 --dry-run -o " + (dir / "f_####.png").string());
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("320x240, 20 fps") && Catch::Contains("follow (--camera follow)"));
  CHECK_THAT(r.output, Catch::Contains("t = 0.2          " + (dir / "f_0005.png").string()));
  CHECK_THAT(r.output, Catch::Contains("t = 0.95         " + (dir / "f_0020.png").string()));
  CHECK_FALSE(fs::exists(dir));
  // Mistakes are found as a render would find them, with the same codes.
  CHECK(runTumble("render " + kSource + "/tests/scenes/cameras.json --camera nope --dry-run").exit_code == 64);
  CHECK(runTumble("render " + kSource + "/tests/scene/bad/camera_follow_no_body.json --dry-run").exit_code == 65);
}
