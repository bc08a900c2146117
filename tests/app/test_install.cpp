// cmake --install gives a tumble that renders with nothing from the source or build tree but the
// scene it is given: run from an unrelated folder, with no shader folder set.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

// Runs `command` through the shell with its output in `log`; returns the exit status.
int runLogged(const std::string& command, const fs::path& log) {
  int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string contents(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("the installed tumble renders a scene from any folder", "[cli][install]") {
  const fs::path root = fs::temp_directory_path() / "tumble_test_install";
  const fs::path prefix = root / "prefix", work = root / "work", log = root / "log.txt";
  fs::remove_all(root);
  fs::create_directories(work);

  const std::string install = std::string("'") + TUMBLE_CMAKE_COMMAND + "' --install '" +
                              TUMBLE_BINARY_DIR + "' --prefix '" + prefix.string() + "'";
  REQUIRE(runLogged(install, log) == 0);
  const fs::path exe = prefix / "bin" / "tumble";
  REQUIRE(fs::exists(exe));

  // t_handle.json names its mesh relative to the scene file (../assets/t_handle.obj).
  const std::string scene = std::string(TUMBLE_SOURCE_DIR) + "/scenes/t_handle.json";
  const std::string render = "cd '" + work.string() + "' && env -u TUMBLE_SHADER_DIR '" +
                             exe.string() + "' render '" + scene +
                             "' -o frames/ --frames 1 --size 160x90 --samples 1 -y -q";
  const int code = runLogged(render, log);
  INFO(contents(log));
  CHECK(code == 0);
  CHECK(fs::exists(work / "frames" / "frame_0001.png"));
  fs::remove_all(root);
}
