// render --time-scale: true slow motion — more frames per simulated second, each at its own
// instant — refused when the step does not divide the new frame interval.
#include <catch2/catch.hpp>

#include <filesystem>

#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

// 10 fps, 10 frames (t = 0 .. 0.9 s), 24 steps of 1/240 s to a frame.
const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

fs::path freshDir(const std::string& name) { return tumble::test::freshTempDir("tumble_time_scale_" + name); }

std::string timeOf(const fs::path& png) {
  for (const tumble::PngText& t : tumble::readPngText(png))
    if (t.keyword == "tumble time s") return t.text;
  return "";
}

}  // namespace

TEST_CASE("render --time-scale 0.25 gives four times the frames over the same simulated span", "[cli][time-scale]") {
  auto r = runTumble("render " + kScene + " --time-scale 0.25 --dry-run -o out/x.mp4");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("37 frames in the clip") && Catch::Contains("6 steps per frame") &&
                           Catch::Contains("time scale 0.25"));
  CHECK_THAT(r.output, Catch::Contains("      2  t = 0.025") && Catch::Contains("     37  t = 0.9"));
}

TEST_CASE("a slow-motion frame shows its exact instant, not a repeated frame", "[cli][time-scale]") {
  fs::path dir = freshDir("instants");
  REQUIRE(runTumble("render -q " + kScene + " --frames 2 -o " + (dir / "normal/").string()).exit_code == 0);
  REQUIRE(runTumble("render -q " + kScene + " --time-scale 0.25 --frames 4..6 -o " + (dir / "slow/").string())
              .exit_code == 0);
  // Slow frame 5 is t = 4 x 0.025 = 0.1 s, the instant normal frame 2 shows: the same picture.
  CHECK(timeOf(dir / "slow" / "frame_0005.png") == "0.1");
  CHECK(timeOf(dir / "normal" / "frame_0002.png") == "0.1");
  CHECK(tumble::readPng(dir / "slow" / "frame_0005.png").pixels == tumble::readPng(dir / "normal" / "frame_0002.png").pixels);
  // Its neighbours are in between instants, each a picture of its own.
  CHECK(timeOf(dir / "slow" / "frame_0004.png") == "0.075");
  CHECK(tumble::readPng(dir / "slow" / "frame_0004.png").pixels != tumble::readPng(dir / "slow" / "frame_0005.png").pixels);
  CHECK(tumble::readPng(dir / "slow" / "frame_0006.png").pixels != tumble::readPng(dir / "slow" / "frame_0005.png").pixels);
}

TEST_CASE("a time scale the step does not divide is a usage error (64), and nothing is written", "[cli][time-scale]") {
  fs::path dir = freshDir("refused");
  // 24 steps x 0.1 = 2.4 steps to a frame: no frame would fall on a step.
  auto r = runTumble("render -q " + kScene + " --time-scale 0.1 -o " + (dir / "f/").string());
  CHECK(r.exit_code == 64);
  CHECK_THAT(r.output, Catch::Contains("--time-scale 0.1: a frame would be 2.4 steps") && Catch::Contains("--dt"));
  CHECK(runTumble("render -q " + kScene + " --time-scale 0 -o " + (dir / "f/").string()).exit_code == 64);
  CHECK(fs::is_empty(dir));
  // A finer step makes it divide: 1/300 s steps, 30 to a frame, 3 to a slow one.
  CHECK(runTumble("render " + kScene + " --dt 0.0033333333 --time-scale 0.1 --dry-run").exit_code == 0);
}

TEST_CASE("a slow-motion clip renders from a trajectory simulated at the same time scale, bit for bit",
          "[cli][time-scale][scale-out]") {
  fs::path dir = freshDir("from_trajectory");
  const std::string csv = (dir / "slow.csv").string();
  REQUIRE(runTumble("simulate -q " + kScene + " --time-scale 0.25 --trajectory " + csv).exit_code == 0);
  REQUIRE(runTumble("render -q " + kScene + " --time-scale 0.25 --frames 5 -o " + (dir / "direct/").string()).exit_code == 0);
  REQUIRE(runTumble("render -q " + kScene + " --time-scale 0.25 --frames 5 --from-trajectory " + csv + " -o " +
                    (dir / "from/").string()).exit_code == 0);
  CHECK(tumble::readPng(dir / "from" / "frame_0005.png").pixels == tumble::readPng(dir / "direct" / "frame_0005.png").pixels);
  // At another scale the trajectory's frames are not the clip's: refused, naming the flag.
  auto r = runTumble("render -q " + kScene + " --frames 5 --from-trajectory " + csv + " -o " + (dir / "normal/").string());
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("--time-scale"));
}
