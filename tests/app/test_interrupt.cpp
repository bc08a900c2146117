// Ctrl-C (SIGINT) and SIGTERM during a render: tumble stops after the current frame, keeps the
// PNGs written so far or finalises a playable video under NAME.partial.mp4 (never the final
// name), says how far it got and exits 130. The signal is sent once output has appeared on disk,
// so the test waits for a state of the files, not for a length of time.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../io/decode_video.h"
#include "../io/temp_dir.h"

namespace fs = std::filesystem;

namespace {

struct Child {
  pid_t pid = -1;
  fs::path log;
};

// Starts tumble with `args`, its stderr and stdout going to `log`.
Child start(const std::vector<std::string>& args, const fs::path& log) {
  std::fflush(nullptr);
  Child c{::fork(), log};
  REQUIRE(c.pid >= 0);
  if (c.pid == 0) {
    int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    std::vector<char*> argv{const_cast<char*>(TUMBLE_EXE)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(TUMBLE_EXE, argv.data());
    ::_exit(127);
  }
  return c;
}

// Waits until `ready` holds (true) or the child has exited (false: it finished too soon).
bool waitFor(const Child& c, const std::function<bool()>& ready) {
  for (int i = 0; i < 60000; ++i) {   // a cap against a broken build, far beyond the need
    if (ready()) return true;
    if (::waitpid(c.pid, nullptr, WNOHANG) == c.pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

int finish(const Child& c) {
  int status = 0;
  ::waitpid(c.pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

std::string text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool hiddenFileIn(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string()[0] == '.') return true;
  return false;
}

// 3001 frames (300 s at 10 fps, t = 0 .. 300 s): minutes of work, so the signal always arrives in
// the middle of the render.
const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

}  // namespace

TEST_CASE("SIGINT during a PNG render keeps the frames so far and exits 130", "[cli][interrupt]") {
  tumble::test::TempDir dir;
  Child c = start({"render", kScene, "--duration", "300", "-o", (dir / "f_####.png").string()}, dir / "log");
  REQUIRE(waitFor(c, [&] { return fs::exists(dir / "f_0002.png"); }));
  ::kill(c.pid, SIGINT);
  CHECK(finish(c) == 130);
  std::string log = text(dir / "log");
  CHECK_THAT(log, Catch::Contains("tumble: interrupted after ") && Catch::Contains(" of 3001 frames"));
  CHECK(fs::exists(dir / "f_0001.png"));
  CHECK_FALSE(fs::exists(dir / "f_3001.png"));
  CHECK_FALSE(hiddenFileIn(dir.path()));   // no half-written frame
}

TEST_CASE("SIGTERM during a video render finalises a playable NAME.partial.mp4", "[cli][interrupt]") {
  tumble::test::TempDir dir;
  Child c = start({"render", kScene, "--duration", "300", "--size", "320x240", "-o", (dir / "clip.mp4").string()},
                  dir / "log");
  // The encoder's output reaches the hidden temporary file in 32 KB blocks: once it has grown
  // past its header, frames have been encoded.
  REQUIRE(waitFor(c, [&] {
    for (const auto& e : fs::directory_iterator(dir.path()))
      if (e.path().filename().string().rfind(".clip.mp4.partial", 0) == 0 && fs::file_size(e.path()) > 1024) return true;
    return false;
  }));
  ::kill(c.pid, SIGTERM);
  CHECK(finish(c) == 130);
  CHECK_THAT(text(dir / "log"), Catch::Contains("interrupted after ") && Catch::Contains("clip.partial.mp4"));
  CHECK_FALSE(fs::exists(dir / "clip.mp4"));
  REQUIRE(fs::exists(dir / "clip.partial.mp4"));
  tumble::test::DecodedVideo video = tumble::test::decodeVideo(dir / "clip.partial.mp4");
  CHECK(video.frames.size() >= 1);
  CHECK(video.width == 320);
  CHECK_FALSE(hiddenFileIn(dir.path()));
}
