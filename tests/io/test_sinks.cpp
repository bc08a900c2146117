#include <catch2/catch.hpp>

#include <fstream>

#include "base/error.h"
#include "decode_video.h"
#include "error_code.h"
#include "io/make_frame_sink.h"
#include "io/png_file.h"
#include "io/png_sequence_sink.h"
#include "io/video_sink.h"
#include "synthetic_image.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;
using test::codeOf;

namespace {

std::size_t fileCount(const fs::path& folder) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

}  // namespace

TEST_CASE("PNG sequence sink creates the folder and numbers frames", "[io][sink]") {
  test::TempDir dir;
  OutputTarget target = parseOutput((dir / "deep/er/").string(), 3);
  auto sink = makeFrameSink(target, SinkOptions{});
  for (int n = 1; n <= 3; ++n) sink->write(test::syntheticImage(32, 24, n), n);
  sink->finish();
  CHECK(sink->describe() == (dir / "deep/er/frame_####.png").string());
  CHECK(fileCount(dir / "deep/er") == 3);
  CHECK(readPng(dir / "deep/er/frame_0002.png").pixels == test::syntheticImage(32, 24, 2).pixels);
}

TEST_CASE("PNG sequence sink never replaces a frame unless told to", "[io][sink]") {
  test::TempDir dir;
  OutputTarget target = parseOutput((dir / "f_##.png").string(), 2);
  writePng(framePath(target, 1), test::syntheticImage(8, 8, 100));
  const auto old = readPng(framePath(target, 1)).pixels;

  PngSequenceSink strict(target, false, false);
  CHECK(codeOf([&] { strict.write(test::syntheticImage(8, 8, 1), 1); }) == ExitCode::CantCreate);
  CHECK(readPng(framePath(target, 1)).pixels == old);

  PngSequenceSink resume(target, false, true);
  resume.write(test::syntheticImage(8, 8, 1), 1);
  resume.write(test::syntheticImage(8, 8, 2), 2);
  CHECK(resume.framesSkipped() == 1);
  CHECK(resume.framesWritten() == 1);
  CHECK(readPng(framePath(target, 1)).pixels == old);

  PngSequenceSink replace(target, true, false);
  replace.write(test::syntheticImage(8, 8, 1), 1);
  CHECK(readPng(framePath(target, 1)).pixels == test::syntheticImage(8, 8, 1).pixels);
}

TEST_CASE("video sink writes under a temporary name until finish", "[io][sink]") {
  test::TempDir dir;
  OutputTarget target = parseOutput((dir / "out/drop.mp4").string(), 4);
  auto sink = makeFrameSink(target, SinkOptions{64, 48, 24, 23, false, false});
  for (int n = 1; n <= 4; ++n) sink->write(test::syntheticImage(64, 48, n), n);
  CHECK_FALSE(fs::exists(dir / "out/drop.mp4"));
  CHECK(fileCount(dir / "out") == 1);   // the hidden partial file
  sink->finish();
  CHECK(fileCount(dir / "out") == 1);
  CHECK(sink->describe() == (dir / "out/drop.mp4").string());
  CHECK(test::decodeVideo(dir / "out/drop.mp4").frames.size() == 4);
  // a second render without overwrite is refused before any work
  CHECK(codeOf([&] { makeFrameSink(target, SinkOptions{64, 48, 24, 23, false, false}); }) ==
        ExitCode::CantCreate);
}

TEST_CASE("an unfinished video sink leaves a playable .partial file", "[io][sink]") {
  test::TempDir dir;
  OutputTarget target = parseOutput((dir / "drop.mp4").string(), 10);
  {
    auto sink = makeFrameSink(target, SinkOptions{64, 48, 24, 23, false, false});
    for (int n = 1; n <= 5; ++n) sink->write(test::syntheticImage(64, 48, n), n);
  }   // destroyed without finish(), as when an error or Ctrl-C unwinds the render
  CHECK_FALSE(fs::exists(dir / "drop.mp4"));
  REQUIRE(fs::exists(dir / "drop.partial.mp4"));
  CHECK(fileCount(dir.path()) == 1);
  CHECK(test::decodeVideo(dir / "drop.partial.mp4").frames.size() == 5);
  {
    auto sink = makeFrameSink(target, SinkOptions{64, 48, 24, 23, false, false});
  }   // nothing written: nothing left behind
  CHECK(fileCount(dir.path()) == 1);
}

TEST_CASE("null sink discards frames", "[io][sink]") {
  auto sink = makeNullSink();
  sink->write(test::syntheticImage(8, 8, 0), 1);
  sink->finish();
  CHECK(sink->describe().find("nothing") != std::string::npos);
}
