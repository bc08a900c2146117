// Hand-written bad scene files, one fault each, in tests/scene/bad/. The first line of each file
// says what tumble must answer:  // expect CODE: NAME.json:LINE:COLUMN: /json/pointer: message
// The message must begin with exactly that (after the folder), and the error carry that exit code.
// A new bad input is a new file; no code changes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "base/error.h"
#include "scene/scene_loader.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

struct Expectation {
  int code = -1;
  std::string message;   // the start of the message, from the file name on
};

Expectation expectationOf(const fs::path& file) {
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  static const std::regex form(R"(// expect (\d+): (.+))");
  std::smatch m;
  Expectation e;
  if (std::regex_match(first, m, form)) e = {std::stoi(m[1]), m[2]};
  return e;
}

std::vector<fs::path> badScenes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/bad"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("every hand-written bad scene is refused at its line, column and field", "[scene][bad]") {
  const std::vector<fs::path> files = badScenes();
  REQUIRE(files.size() >= 40);
  for (const fs::path& file : files) {
    const Expectation expected = expectationOf(file);
    INFO(file.filename().string());
    REQUIRE(expected.code > 0);   // the file states what it expects
    std::string message;
    int code = 0;
    try {
      loadScene(file);
    } catch (const Error& e) {
      message = e.what();
      code = static_cast<int>(e.code());
    }
    CHECK(code == expected.code);
    CHECK_THAT(message, Catch::StartsWith((file.parent_path() / expected.message).string()));
  }
}

TEST_CASE("a scene that is a device or a folder is refused without reading it", "[scene][bad]") {
  for (const char* path : {"/dev/zero", "/tmp"}) {
    INFO(path);
    try {
      loadScene(path);
      FAIL("no error");
    } catch (const Error& e) {
      CHECK(e.code() == ExitCode::MissingInput);
      CHECK_THAT(e.what(), Catch::StartsWith(std::string(path) + ": is "));
    }
  }
}
