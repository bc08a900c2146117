// Video parts: their names, and joining them by stream copy.
#include <catch2/catch.hpp>

#include "decode_video.h"
#include "error_code.h"
#include "io/video_join.h"
#include "io/video_writer.h"
#include "synthetic_image.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;
using test::codeOf;

namespace {

// Frames first..last of one synthetic clip, as a part of `count`.
fs::path writePart(const test::TempDir& dir, int index, int count, int first, int last, int width = 64) {
  fs::path path = videoPartPath(dir / "clip.mp4", index, count);
  VideoSettings settings;
  settings.width = width;
  settings.height = 48;
  settings.fps = 25;
  settings.threads = 1;
  VideoWriter writer(path, settings);
  for (int f = first; f <= last; ++f) writer.write(test::syntheticImage(width, 48, f));
  writer.finish();
  return path;
}

}  // namespace

TEST_CASE("video part names carry the whole video's name and the part's place", "[io][join]") {
  CHECK(videoPartPath("out/clip.mp4", 3, 8) == fs::path("out/clip.part-0003-of-0008.mp4"));
  CHECK(videoPartPath("a.b.mkv", 12, 12345) == fs::path("a.b.part-0012-of-12345.mkv"));
  std::optional<VideoPartName> name = parseVideoPartName("out/clip.part-0003-of-0008.mp4");
  REQUIRE(name);
  CHECK(name->video == fs::path("out/clip.mp4"));
  CHECK((name->index == 3 && name->count == 8));
  for (const char* bad : {"out/clip.mp4", "clip.part-0009-of-0008.mp4", "clip.part-x-of-0008.mp4", "clip.part-0000-of-0008.mp4"})
    CHECK_FALSE(parseVideoPartName(bad));
}

TEST_CASE("joined parts decode to the parts' pictures in order, with one frame interval between all", "[io][join]") {
  test::TempDir dir;
  std::vector<fs::path> parts = {writePart(dir, 2, 3, 8, 20), writePart(dir, 1, 3, 1, 7), writePart(dir, 3, 3, 21, 30)};
  JoinSummary summary = joinVideoParts(dir / "clip.mp4", parts, false);
  CHECK(summary.parts == 3);
  CHECK(summary.frames == 30);
  test::DecodedVideo joined = test::decodeVideo(dir / "clip.mp4");
  REQUIRE(joined.frames.size() == 30);
  CHECK(joined.duration == Approx(30 / 25.0).margin(1e-3));
  std::vector<std::vector<std::uint8_t>> luma;
  for (int i : {1, 0, 2}) {
    test::DecodedVideo p = test::decodeVideo(parts[static_cast<std::size_t>(i)]);
    luma.insert(luma.end(), p.luma.begin(), p.luma.end());
  }
  CHECK(luma == joined.luma);
  std::vector<std::string> boxes = test::topLevelBoxes(dir / "clip.mp4");
  auto at = [&](const std::string& box) { return std::find(boxes.begin(), boxes.end(), box) - boxes.begin(); };
  CHECK(at("moov") < at("mdat"));   // faststart, as tumble's own videos
}

TEST_CASE("join refuses unlike or incomplete parts and leaves no output", "[io][join]") {
  test::TempDir dir;
  fs::path one = writePart(dir, 1, 2, 1, 5);
  fs::path wide = writePart(dir, 2, 2, 6, 10, 80);
  CHECK(codeOf([&] { joinVideoParts(dir / "clip.mp4", {one, wide}, false); }) == ExitCode::BadInput);
  CHECK(codeOf([&] { joinVideoParts(dir / "clip.mp4", {one}, false); }) == ExitCode::BadInput);
  CHECK(codeOf([&] { joinVideoParts(dir / "clip.mp4", {one, dir / "clip.part-0002-of-0002.mkv"}, false); }) ==
        ExitCode::BadInput);   // another video's part
  fs::remove(wide);
  CHECK(codeOf([&] { joinVideoParts(dir / "clip.mp4", {one, wide}, false); }) == ExitCode::MissingInput);
  CHECK_FALSE(fs::exists(dir / "clip.mp4"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
  CHECK(files == 1);   // no temporary file left behind
}
