// --version names the project version and the commit, as the benchmark's pages and bug reports
// rely on.
#include <catch2/catch.hpp>

#include <regex>

#include "run_tumble.h"

using tumble::test::runTumble;

TEST_CASE("tumble --version prints the project version and the commit", "[cli][install]") {
  auto r = runTumble("--version");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::StartsWith(std::string("tumble ") + TUMBLE_PROJECT_VERSION + " "));
  // A short hash, "-dirty" after it when the tree had changes; "unknown" outside git.
  CHECK(std::regex_search(r.output, std::regex(R"(\(commit ([0-9a-f]{7,}(-dirty)?|unknown)\))")));
}
