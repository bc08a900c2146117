// The whole benchmark in --quick mode, as the README runs it: checks that it finishes, writes its
// CSV and a plot per scene, and that every metric of every engine is finite. Never a timing.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) { out.push_back(field); field.clear(); }
    else field += c;
  }
  out.push_back(field);
  return out;
}

}  // namespace

TEST_CASE("tumble-bench --quick writes a CSV of finite metrics and a plot per scene") {
  const fs::path out = fs::path(TUMBLE_BINARY_DIR) / "bench-quick";
  fs::remove_all(out);
  const std::string cmd = std::string(TUMBLE_BENCH_EXE) + " --quick -o " + out.string() + " > " +
                          (fs::path(TUMBLE_BINARY_DIR) / "bench-quick.log").string() + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  std::ifstream csv(out / "results.csv");
  REQUIRE(csv);
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = splitCsv(line);
  REQUIRE(header.size() == 15);
  std::set<std::string> scenes, engines;
  int rows = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = splitCsv(line);
    REQUIRE(f.size() == 15);
    INFO(line);
    scenes.insert(f[0]);
    engines.insert(f[2]);
    CHECK(f[10] == "0");                                   // the run did not fail
    CHECK(std::isfinite(std::strtod(f[5].c_str(), nullptr)));   // wall s per simulated s
    CHECK(std::isfinite(std::strtod(f[12].c_str(), nullptr)));  // the metric's value
    ++rows;
  }
  CHECK(rows > 50);
  CHECK(engines.count("tumble") == 1);
  CHECK(scenes.size() == 10);
  for (const std::string& s : scenes) CHECK(fs::file_size(out / (s + ".png")) > 1000);
}
