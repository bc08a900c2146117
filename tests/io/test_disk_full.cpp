// A full disk while writing: every output gives a clear CantCreate error and leaves nothing under
// its final name and no temporary file behind. The disk is "full" through RLIMIT_FSIZE in a child
// process: a write past the limit fails (EFBIG) exactly where a full disk would (ENOSPC), without
// root, a mount or filling a real disk.
#include <catch2/catch.hpp>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/error.h"
#include "io/png_file.h"
#include "io/trajectory_csv.h"
#include "io/video_sink.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

// What the child saw, as its exit status.
enum Verdict { kClearError = 0, kNoError = 1, kOtherError = 2, kFinalNameExists = 3, kTempLeft = 4 };

// Noise does not compress: a 128x128 frame is ~48 KB in any format.
RgbImage noise(int seed) {
  RgbImage image;
  image.width = image.height = 128;
  image.pixels.resize(128 * 128 * 3);
  std::mt19937 random(seed);
  for (auto& p : image.pixels) p = static_cast<std::uint8_t>(random());
  return image;
}

// Runs `write` in a child whose files may not grow past 16 KB, and checks what it left in `dir`.
int writeWithFullDisk(const fs::path& dir, const fs::path& final_path, const std::function<void()>& write) {
  std::fflush(nullptr);
  pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);   // a failed write, not a killed process, as with ENOSPC
    rlimit limit{16 * 1024, 16 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int verdict = kNoError;
    try {
      write();
    } catch (const Error& e) {
      std::string what = e.what();
      bool clear = e.code() == ExitCode::CantCreate && what.find("cannot write " + final_path.string()) == 0;
      verdict = clear ? kClearError : kOtherError;
      if (!clear) std::fprintf(stderr, "unclear error: %s\n", what.c_str());
    } catch (...) {
      verdict = kOtherError;
    }
    if (verdict == kClearError && fs::exists(final_path)) verdict = kFinalNameExists;
    if (verdict == kClearError)
      for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string()[0] == '.') verdict = kTempLeft;
    ::_exit(verdict);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

}  // namespace

TEST_CASE("a full disk while writing a PNG is CantCreate and leaves nothing", "[io][disk-full]") {
  test::TempDir dir;
  CHECK(writeWithFullDisk(dir.path(), dir / "frame_0001.png",
                          [&] { writePng(dir / "frame_0001.png", noise(1), false); }) == kClearError);
}

TEST_CASE("a full disk while writing a trajectory CSV is CantCreate and leaves nothing", "[io][disk-full]") {
  test::TempDir dir;
  CHECK(writeWithFullDisk(dir.path(), dir / "t.csv", [&] {
          CsvTrajectoryWriter csv(dir / "t.csv", false);
          const double values[CsvTrajectoryWriter::kValues] = {0.1, 0.2, 0.3, 1, 0, 0, 0, 1, 2, 3, 4, 5, 6};
          for (int i = 0; i < 2000; ++i) csv.row(i / 240.0, "body", values);
          csv.close();
        }) == kClearError);
}

TEST_CASE("a full disk while encoding a video is CantCreate and leaves no video under its name", "[io][disk-full]") {
  test::TempDir dir;
  const fs::path video = dir / "clip.mp4";
  int verdict = writeWithFullDisk(dir.path(), video, [&] {
    OutputTarget target;
    target.path = video;
    VideoSink sink(target, VideoSettings{128, 128, 24, 0, "veryfast"}, false);
    for (int i = 0; i < 48; ++i) sink.write(noise(i), i + 1);
    sink.finish();
  });
  CHECK(verdict == kClearError);
  CHECK_FALSE(fs::exists(video));
}
