// The whole path, as a user runs it: scene file -> simulation -> OSMesa frames -> PNG sequence and
// H.264 MP4; then the PNGs are read back and the MP4 decoded with libavformat/libavcodec.
#include <catch2/catch.hpp>

#include <filesystem>

#include "../io/decode_video.h"
#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

struct Census {
  int box = 0, sky = 0, ground = 0;   // pixels of each kind
};

// Classifies pixels by colour: the box is a saturated orange-red, the sky a pale blue, the ground
// a neutral grey (lit or in shadow). Thresholds are loose: shading moves colours a lot, hues little.
Census census(const tumble::RgbImage& img, int row_begin, int row_end) {
  Census c;
  for (int y = row_begin; y < row_end; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = &img.pixels[3 * (y * img.width + x)];
      int r = p[0], g = p[1], b = p[2];
      if (r > g + 60 && r > b + 60) ++c.box;
      else if (b > r + 12 && b > 180) ++c.sky;
      else if (std::abs(r - g) < 14 && std::abs(g - b) < 14) ++c.ground;
    }
  }
  return c;
}

void checkFrameShowsScene(const tumble::RgbImage& img) {
  REQUIRE(img.width == 160);
  REQUIRE(img.height == 120);
  Census top = census(img, 0, 12);          // the camera looks down at the horizon: sky on top
  Census bottom = census(img, 108, 120);    // and ground at the bottom (not upside down)
  Census all = census(img, 0, 120);
  CHECK(top.sky > top.ground);
  CHECK(bottom.ground > 100);
  CHECK(all.box > 50);                      // the box is in view
}

}  // namespace

TEST_CASE("render to a PNG sequence: 10 frames, right size, showing the scene", "[e2e]") {
  fs::path dir = fs::temp_directory_path() / "tumble_e2e_png";
  fs::remove_all(dir);
  auto r = runTumble("render " + kScene + " -o '" + (dir / "frame_####.png").string() + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("rendered 10 of 10 frames"));
  for (int k = 1; k <= 10; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", k);
    REQUIRE(fs::exists(dir / name));
    checkFrameShowsScene(tumble::readPng(dir / name));
  }
  CHECK_FALSE(fs::exists(dir / "frame_0011.png"));
  CHECK_FALSE(fs::exists(dir / "frame_0000.png"));   // frames count from 1
}

TEST_CASE("render to MP4: H.264, yuv420p, 10 frames, 1 s, playable", "[e2e]") {
  fs::path dir = fs::temp_directory_path() / "tumble_e2e_mp4";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto r = runTumble("render " + kScene + " -o " + (dir / "clip.mp4").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  tumble::test::DecodedVideo video = tumble::test::decodeVideo(dir / "clip.mp4");
  CHECK(video.codec == "h264");
  CHECK(video.pix_fmt == "yuv420p");
  CHECK(video.width == 160);
  CHECK(video.height == 120);
  CHECK(video.fps == Approx(10));
  CHECK(video.duration == Approx(1.0).margin(0.1 / 2));   // within half a frame
  REQUIRE(video.frames.size() == 10);
  checkFrameShowsScene(video.frames.front());
  checkFrameShowsScene(video.frames.back());
  // Nothing but the video is left in the folder (no temporaries).
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("a frame range renders only those frames, numbered as in the full clip", "[e2e]") {
  fs::path dir = fs::temp_directory_path() / "tumble_e2e_range";
  fs::remove_all(dir);
  auto r = runTumble("render " + kScene + " -q --frames 2,5..6 -o " + dir.string() + "/");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir / "frame_0002.png"));
  CHECK(fs::exists(dir / "frame_0005.png"));
  CHECK(fs::exists(dir / "frame_0006.png"));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);
  // --skip-existing resumes: only the missing frames are rendered.
  auto resume = runTumble("render " + kScene + " -s 5 -e 7 --skip-existing -o " + dir.string() + "/");
  REQUIRE(resume.exit_code == 0);
  CHECK_THAT(resume.output, Catch::Contains("rendered 1 of 1 frames"));
  CHECK(fs::exists(dir / "frame_0007.png"));
}
