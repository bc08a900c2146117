#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "decode_video.h"
#include "error_code.h"
#include "io/video_writer.h"
#include "synthetic_image.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;
using test::codeOf;

namespace {

void writeClip(const fs::path& path, int width, int height, int fps, int frames) {
  VideoWriter writer(path, VideoSettings{width, height, fps, 23, "veryfast"});
  for (int i = 0; i < frames; ++i) writer.write(test::syntheticImage(width, height, i));
  writer.finish();
  CHECK(writer.framesWritten() == frames);
}

}  // namespace

TEST_CASE("H.264 MP4 round trip: frames, timing, format, colour", "[io][video]") {
  test::TempDir dir;
  fs::path path = dir / "clip.mp4";
  writeClip(path, 160, 120, 24, 12);
  test::DecodedVideo v = test::decodeVideo(path);
  CHECK(v.frames.size() == 12);
  CHECK(v.width == 160);
  CHECK(v.height == 120);
  CHECK(v.fps == Approx(24));
  CHECK(std::abs(v.duration - 0.5) <= 1.0 / 24);
  CHECK(v.codec == "h264");
  CHECK(v.pix_fmt == "yuv420p");
  CHECK(v.color_primaries == "bt709");
  CHECK(v.color_space == "bt709");
  CHECK(v.color_range == "tv");
  RgbImage first = test::syntheticImage(160, 120, 0);
  for (int c = 0; c < 3; ++c) {
    CHECK(test::meanChannel(v.frames[0], c) == Approx(test::meanChannel(first, c)).margin(3));
  }
  // faststart: the index comes before the media data
  std::vector<std::string> boxes = test::topLevelBoxes(path);
  auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  REQUIRE(moov != boxes.end());
  REQUIRE(mdat != boxes.end());
  CHECK(moov < mdat);
}

TEST_CASE("the RGB to YUV conversion uses the BT.709 matrix it is tagged with", "[io][video]") {
  // Pure red has luma 0.2126 in BT.709 but 0.299 in BT.601: limited-range Y of 63 versus 82.
  test::TempDir dir;
  RgbImage red{64, 64, {}};
  red.pixels.resize(64 * 64 * 3);
  for (std::size_t i = 0; i < red.pixels.size(); i += 3) red.pixels[i] = 255;
  VideoWriter writer(dir / "red.mkv", VideoSettings{64, 64, 10, 18, "veryfast"});
  writer.write(red);
  writer.finish();
  test::DecodedVideo v = test::decodeVideo(dir / "red.mkv");
  REQUIRE(v.luma.size() == 1);
  double y = 0;
  for (std::uint8_t l : v.luma[0]) y += l;
  y /= static_cast<double>(v.luma[0].size());
  CHECK(y == Approx(16 + 219 * 0.2126).margin(1.5));
}

TEST_CASE("MKV and MOV containers follow the extension", "[io][video]") {
  test::TempDir dir;
  for (const char* name : {"clip.mkv", "clip.mov"}) {
    writeClip(dir / name, 96, 64, 30, 6);
    test::DecodedVideo v = test::decodeVideo(dir / name);
    CHECK(v.frames.size() == 6);
    CHECK(v.codec == "h264");
    CHECK(std::abs(v.duration - 0.2) <= 1.0 / 30);
  }
}

TEST_CASE("odd sizes are refused with a hint", "[io][video]") {
  test::TempDir dir;
  CHECK(codeOf([&] { VideoWriter(dir / "odd.mp4", VideoSettings{161, 120, 24, 23, "veryfast"}); })
        == ExitCode::BadInput);
  CHECK_THROWS_WITH(VideoWriter(dir / "odd.mp4", VideoSettings{160, 121, 24, 23, "veryfast"}),
                    Catch::Contains("even") && Catch::Contains("--size 1280x720"));
}

TEST_CASE("a frame of the wrong size and an unwritable path are CantCreate", "[io][video]") {
  test::TempDir dir;
  VideoWriter writer(dir / "a.mp4", VideoSettings{64, 64, 24, 23, "veryfast"});
  CHECK(codeOf([&] { writer.write(test::syntheticImage(32, 32, 0)); }) == ExitCode::CantCreate);
  const VideoSettings small{64, 64, 24, 23, "veryfast"};
  CHECK(codeOf([&] { VideoWriter(dir / "no/such/dir/a.mp4", small); }) == ExitCode::CantCreate);
}
