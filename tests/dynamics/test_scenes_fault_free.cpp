// The run-time fault check (fault_check.h: NaN, runaway energy, deep overlap, a body moved farther
// than its speeds allow, energy gained above its running minimum) must not trip on a healthy
// scene: every scene of scenes/ (the hard cases have their own tests, some of them marked known
// failures because they do trip it) runs its first second, with its own settings and contact model,
// without a fault. runScene stops a run on the first fault with an error naming it. The course
// demos of scenes/demos/ are held to the same: each loads and simulates its first second.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "contact_scene_runner.h"

using namespace tumble;

TEST_CASE("every scene of scenes/ runs its first second without a run-time fault", "[faults][scenes]") {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(TUMBLE_SOURCE_DIR) + "/scenes"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  REQUIRE(names.size() >= 10);
  for (const std::string& name : names) {
    INFO(name);
    // Overlaps are measured only at the end: the fault check itself watches every step.
    CHECK_NOTHROW(test::runScene(name, 1.0, {}, 1000000));
  }
}

TEST_CASE("every course demo of scenes/demos/ loads and runs its first second without a run-time fault",
          "[faults][scenes][demos]") {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(TUMBLE_SOURCE_DIR) + "/scenes/demos"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") names.push_back("demos/" + entry.path().stem().string());
  std::sort(names.begin(), names.end());
  REQUIRE(names.size() >= 10);
  for (const std::string& name : names) {
    INFO(name);
    CHECK_NOTHROW(test::runScene(name, 1.0, {}, 1000000));
  }
}
