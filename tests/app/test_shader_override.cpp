// The built-in shaders are the default; --shaders or TUMBLE_SHADER_DIR reads a folder instead.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kMissing = "/nonexistent/tumble/shaders";

std::string renderArgs() {
  const fs::path out = fs::temp_directory_path() / "tumble_test_shader_override";
  fs::remove_all(out);
  return std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json -o " + out.string() +
         "/ --frames 1 --size 64x36 --samples 1 -y -q";
}

}  // namespace

TEST_CASE("render reads the GLSL from the folder given by --shaders or TUMBLE_SHADER_DIR", "[cli][install]") {
  auto flag = runTumble("render " + renderArgs() + " --shaders " + kMissing);
  CHECK(flag.exit_code == 66);
  CHECK_THAT(flag.output, Catch::Contains(kMissing + "/lit.vert"));

  ::setenv("TUMBLE_SHADER_DIR", kMissing.c_str(), 1);   // the child inherits it
  auto env = runTumble("render " + renderArgs());
  ::unsetenv("TUMBLE_SHADER_DIR");
  CHECK(env.exit_code == 66);
  CHECK_THAT(env.output, Catch::Contains(kMissing + "/lit.vert"));

  auto source =
      runTumble("render " + renderArgs() + " --shaders " + TUMBLE_SOURCE_DIR + "/shaders");
  CHECK(source.exit_code == 0);
}
