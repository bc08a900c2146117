// render --compare-models through the real executable: each tile is the scene under its model, as
// --contact-model renders it alone at the tile's size, with a label over its top-left corner; bad
// names and flags a comparison cannot honour are a bad command line; the frames are deterministic.
#include <catch2/catch.hpp>

#include <filesystem>

#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::freshTempDir;
using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kCubeDrop = std::string(TUMBLE_SOURCE_DIR) + "/scenes/cube_drop.json";
constexpr int kFrame = 40;   // after the first bounce, where the models' cubes stand apart

// Pixels of `a` at (x0 + x, y) against `b` at (x, y), over columns [0, w) and rows [y0, y1):
// how many differ.
int differing(const tumble::RgbImage& a, int x0, const tumble::RgbImage& b, int w, int y0, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.pixels[(static_cast<std::size_t>(y) * a.width + x0 + x) * 3 + c] !=
            b.pixels[(static_cast<std::size_t>(y) * b.width + x) * 3 + c]) {
          ++n;
          break;
        }
  return n;
}

}  // namespace

TEST_CASE("compare-models tiles two models left and right, each as rendered alone, each labelled", "[compare][cli]") {
  const fs::path dir = freshTempDir("tumble_compare_tiles");
  const std::string at = " --frames " + std::to_string(kFrame) + " -q -o ";
  REQUIRE(runTumble("render " + kCubeDrop + " --size 160x120 --compare-models baraff,penalty" + at +
                    (dir / "both/").string()).exit_code == 0);
  REQUIRE(runTumble("render " + kCubeDrop + " --size 80x120 --contact-model baraff" + at + (dir / "b/").string())
              .exit_code == 0);
  REQUIRE(runTumble("render " + kCubeDrop + " --size 80x120 --contact-model penalty" + at + (dir / "p/").string())
              .exit_code == 0);
  const std::string name = "frame_00" + std::to_string(kFrame) + ".png";
  const tumble::RgbImage both = tumble::readPng(dir / "both" / name);
  const tumble::RgbImage baraff = tumble::readPng(dir / "b" / name), penalty = tumble::readPng(dir / "p" / name);
  REQUIRE(both.width == 160);
  REQUIRE(both.height == 120);
  // Below the labels (8 px text: about 40 rows), each half is its model's own render; the left
  // tile's last column is the seam between them.
  CHECK(differing(both, 0, baraff, 79, 45, 120) == 0);
  CHECK(differing(both, 80, penalty, 80, 45, 120) == 0);
  // The models differ, so the halves do, where the cubes stand.
  CHECK(differing(baraff, 0, penalty, 80, 45, 120) > 20);
  // Each tile carries its label over its top-left corner.
  CHECK(differing(both, 0, baraff, 79, 0, 40) > 200);
  CHECK(differing(both, 80, penalty, 79, 0, 40) > 200);
}

TEST_CASE("compare-models refuses unknown models with did-you-mean and flags it cannot honour", "[compare][cli]") {
  const fs::path dir = freshTempDir("tumble_compare_refused");
  const std::string out = " --frames 1 --size 160x120 -o " + (dir / "f/").string();
  const std::pair<const char*, const char*> refused[] = {
      {"baraff,penalti", "--compare-models: unknown contact model \"penalti\"; did you mean \"penalty\"?"},
      {"baraff", "name two or three models"},
      {"baraff,baraff", "baraff is named twice"},
      {"baraff,penalty --shard 1/2", "--compare-models cannot be combined with --shard"},
      {"baraff,penalty --from-trajectory x.csv", "cannot be combined with --from-trajectory"},
      {"baraff,penalty --contact-model baraff", "cannot be combined with --contact-model"},
  };
  for (const auto& [args, message] : refused) {
    INFO(args);
    auto r = runTumble("render " + kCubeDrop + out + " --compare-models " + args);
    CHECK(r.exit_code == 64);
    CHECK_THAT(r.output, Catch::Contains(message));
  }
  CHECK_FALSE(fs::exists(dir / "f"));   // all refused before any work
}

TEST_CASE("compare-models of three models renders the same frames on every run", "[compare][cli]") {
  const fs::path dir = freshTempDir("tumble_compare_repeat");
  const std::string render = "render " + kCubeDrop + " --size 160x120 --frames 1,30 -q --compare-models "
                             "baraff,time_stepping,penalty -o ";
  REQUIRE(runTumble(render + (dir / "a/").string()).exit_code == 0);
  REQUIRE(runTumble(render + (dir / "b/").string()).exit_code == 0);
  CHECK(runTumble("diff -q --threshold 0 " + (dir / "a").string() + " " + (dir / "b").string()).exit_code == 0);
  const tumble::RgbImage a = tumble::readPng(dir / "a/frame_0030.png"), b = tumble::readPng(dir / "b/frame_0030.png");
  CHECK(a.pixels == b.pixels);
  // 2x2: the bottom-right cell holds no scene, only the background and the scene's name.
  CHECK(differing(a, 80, a, 80, 60, 120) != 0);   // not a copy of the bottom-left cell
  const std::size_t corner = (static_cast<std::size_t>(118) * a.width + 158) * 3;
  CHECK(a.pixels[corner] == 28);
  CHECK(a.pixels[corner + 2] == 36);
}
