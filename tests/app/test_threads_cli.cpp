// --threads N on the command line: faster on several cores, never different. The trajectory a pile
// writes with two threads must be byte for byte the one it writes with one.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  return all.str();
}

}  // namespace

TEST_CASE("simulate --threads 2 writes the same trajectory bytes as one thread", "[cli][threads][determinism]") {
  const fs::path dir = tumble::test::freshTempDir("tumble_threads");
  const std::string scene = std::string(TUMBLE_SOURCE_DIR) + "/scenes/pile_time_stepping.json";
  auto one = runTumble("simulate -q " + scene + " --duration 1 --every-step --trajectory " + (dir / "one.csv").string());
  REQUIRE(one.exit_code == 0);
  auto two = runTumble("simulate -q " + scene + " --duration 1 --every-step --threads 2 --trajectory " +
                       (dir / "two.csv").string());
  REQUIRE(two.exit_code == 0);
  const std::string a = readAll(dir / "one.csv"), b = readAll(dir / "two.csv");
  REQUIRE(a.size() > 10000);
  CHECK(a == b);
}

TEST_CASE("a negative --threads is refused with exit 64", "[cli][threads]") {
  auto r = runTumble("simulate -q " + std::string(TUMBLE_SOURCE_DIR) + "/scenes/cube_drop.json --threads -1");
  CHECK(r.exit_code == 64);
  CHECK(r.output.find("--threads") != std::string::npos);
}
