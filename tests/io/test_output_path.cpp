#include <catch2/catch.hpp>

#include <fstream>

#include "base/error.h"
#include "error_code.h"
#include "io/output_path.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;
using Kind = OutputTarget::Kind;
using test::codeOf;

TEST_CASE("#### is a zero-padded frame number, counted from 1", "[io][output]") {
  OutputTarget t = parseOutput("out/frame_####.png", 250);
  CHECK(t.kind == Kind::PngSequence);
  CHECK(t.pad == 4);
  CHECK(t.path == fs::path("out/frame_####.png"));
  CHECK(t.pattern == "out/frame_%04d.png");
  CHECK(framePath(t, 1) == fs::path("out/frame_0001.png"));
  CHECK(framePath(t, 250) == fs::path("out/frame_0250.png"));
  CHECK(framePath(t, 12345) == fs::path("out/frame_12345.png"));   // wider numbers grow
}

TEST_CASE("the run of # sets the padding", "[io][output]") {
  CHECK(framePath(parseOutput("f#.png", 20), 7) == fs::path("f7.png"));
  CHECK(framePath(parseOutput("f######.png", 20), 7) == fs::path("f000007.png"));
  CHECK(framePath(parseOutput("f_##_x.png", 20), 3) == fs::path("f_03_x.png"));
}

TEST_CASE("printf spelling %04d and %d", "[io][output]") {
  OutputTarget t = parseOutput("shots/s_%04d.png", 10);
  CHECK(t.kind == Kind::PngSequence);
  CHECK(t.pad == 4);
  CHECK(t.path == fs::path("shots/s_####.png"));
  CHECK(framePath(t, 3) == fs::path("shots/s_0003.png"));
  OutputTarget bare = parseOutput("s_%d.png", 10);
  CHECK(bare.pad == 1);
  CHECK(framePath(bare, 10) == fs::path("s_10.png"));
  CHECK(parseOutput("100%_%03d.png", 2).pattern == "100%%_%03d.png");   // literal % escaped
}

TEST_CASE("a folder means folder/frame_####.png", "[io][output]") {
  OutputTarget t = parseOutput("renders/drop/", 100);
  CHECK(t.kind == Kind::PngSequence);
  CHECK(t.pad == 4);
  CHECK(framePath(t, 1) == fs::path("renders/drop/frame_0001.png"));
  test::TempDir dir;   // an existing folder works without the slash
  CHECK(framePath(parseOutput(dir.path().string(), 3), 2) == dir / "frame_0002.png");
}

TEST_CASE("video extensions pick a video", "[io][output]") {
  for (const char* name : {"out/drop.mp4", "a.mkv", "b.mov", "C.MP4"}) {
    OutputTarget t = parseOutput(name, 100);
    CHECK(t.kind == Kind::Video);
    CHECK(t.path == fs::path(name));
    CHECK(framePath(t, 5) == fs::path(name));
  }
}

TEST_CASE("a single .png is one frame only", "[io][output]") {
  OutputTarget t = parseOutput("still.png", 1);
  CHECK(t.kind == Kind::PngSequence);
  CHECK(t.pad == 0);
  CHECK(framePath(t, 17) == fs::path("still.png"));
  CHECK(codeOf([] { parseOutput("still.png", 2); }) == ExitCode::Usage);
  CHECK_THROWS_WITH(parseOutput("out/still.png", 2), Catch::Contains("out/still_####.png"));
}

TEST_CASE("unknown outputs are usage errors naming the forms that work", "[io][output]") {
  CHECK(codeOf([] { parseOutput("clip.avi", 10); }) == ExitCode::Usage);
  CHECK_THROWS_WITH(parseOutput("clip.avi", 10),
                    Catch::Contains(".mp4") && Catch::Contains("####"));
  CHECK(codeOf([] { parseOutput("frame_####.jpg", 10); }) == ExitCode::Usage);
  CHECK(codeOf([] { parseOutput("no_extension_here", 10); }) == ExitCode::Usage);
  CHECK(codeOf([] { parseOutput("", 10); }) == ExitCode::Usage);
}

TEST_CASE("existingOutputs lists the frames already on disk", "[io][output]") {
  test::TempDir dir;
  OutputTarget seq = parseOutput((dir / "f_###.png").string(), 5);
  std::ofstream(framePath(seq, 2)) << "x";
  std::ofstream(framePath(seq, 4)) << "x";
  CHECK(existingOutputs(seq, {1, 2, 3, 4, 5}) ==
        std::vector<fs::path>{dir / "f_002.png", dir / "f_004.png"});
  CHECK(existingOutputs(seq, {1, 3}).empty());
  OutputTarget video = parseOutput((dir / "v.mp4").string(), 5);
  CHECK(existingOutputs(video, {1, 2}).empty());
  std::ofstream(dir / "v.mp4") << "x";
  CHECK(existingOutputs(video, {1, 2}) == std::vector<fs::path>{dir / "v.mp4"});
}
