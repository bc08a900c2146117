// The hand-written bad scenes of tests/scene/bad/ through the real command line: `tumble check`
// must print "tumble: FILE:LINE:COLUMN: /pointer: message" and exit with the documented code
// (each file's first line says which; tests/scene/test_bad_scenes.cpp checks the loader alone).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "run_tumble.h"

namespace fs = std::filesystem;

TEST_CASE("tumble check answers each bad scene with its exit code and located message", "[cli][bad]") {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/bad"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 40);
  static const std::regex form(R"(// expect (\d+): (.+))");
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    std::smatch m;
    REQUIRE(std::regex_match(first, m, form));
    INFO(file.filename().string());
    tumble::test::RunResult r = tumble::test::runTumble("check " + file.string());
    CHECK(r.exit_code == std::stoi(m[1]));
    CHECK_THAT(r.output, Catch::StartsWith("tumble: " + (file.parent_path() / m[2].str()).string()));
  }
}

TEST_CASE("an odd frame size for a video is refused before any work, saying what to change", "[cli][bad]") {
  const fs::path out = fs::temp_directory_path() / "tumble_odd_size.mp4";
  fs::remove(out);
  tumble::test::RunResult r = tumble::test::runTumble(std::string("render ") + TUMBLE_SOURCE_DIR +
                                                      "/tests/scenes/small_box.json --size 161x120 -o " +
                                                      out.string());
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("yuv420p needs even sizes") && !Catch::Contains("simulate"));
  CHECK_FALSE(fs::exists(out));
}
