// The whole benchmark in --quick mode, as the README runs it: checks that it finishes, writes its
// CSV, a plot per scene (PNG and SVG) and the results page, and that every metric of every engine
// is finite; then redraws the plots from the CSV. Never a timing.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "bench_test_support.h"

using tumble::bench::testing::fileBytes;

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

int runBench(const std::string& args, const std::string& log) {
  const std::string cmd = std::string(TUMBLE_BENCH_EXE) + " " + args + " > " +
                          (fs::path(TUMBLE_BINARY_DIR) / log).string() + " 2>&1";
  return std::system(cmd.c_str());
}

}  // namespace

TEST_CASE("tumble-bench --quick --docs writes a CSV of finite metrics, a plot per scene and the page") {
  const fs::path out = fs::path(TUMBLE_BINARY_DIR) / "bench-quick";
  fs::remove_all(out);
  REQUIRE(runBench("--quick --docs " + out.string(), "bench-quick.log") == 0);
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
  for (const std::string& s : scenes) {
    CHECK(fs::file_size(out / (s + ".png")) > 1000);
    CHECK(fs::file_size(out / (s + ".svg")) > 1000);
  }

  // --plot-from redraws the plots from the CSV alone, the same bytes in two fresh processes.
  const fs::path again1 = fs::path(TUMBLE_BINARY_DIR) / "bench-plot-from-1", again2 = fs::path(TUMBLE_BINARY_DIR) / "bench-plot-from-2";
  fs::remove_all(again1);
  fs::remove_all(again2);
  REQUIRE(runBench("--plot-from " + (out / "results.csv").string() + " -o " + again1.string(), "bench-plot-from-1.log") == 0);
  REQUIRE(runBench("--plot-from " + (out / "results.csv").string() + " -o " + again2.string(), "bench-plot-from-2.log") == 0);
  CHECK(!fs::exists(again1 / "results.csv"));
  for (const std::string& s : scenes)
    for (const char* ext : {".png", ".svg"}) {
      INFO(s << ext);
      CHECK(fs::file_size(again1 / (s + ext)) > 1000);
      CHECK(fileBytes(again1 / (s + ext)) == fileBytes(again2 / (s + ext)));
    }

  // The page: stamped, complete, and a table under the plot of every scene that ran.
  const std::string page = fileBytes(out / "results.md");
  CHECK(page.find("| command | `tumble-bench --quick --docs ") != std::string::npos);
  for (const char* field : {"| date | 2", "| commit | ", "| build type | ", "| machine | ", "| engines | tumble "})
    CHECK(page.find(field) != std::string::npos);
  CHECK(page.find("partial") == std::string::npos);
  CHECK(page.find("| command | `tumble-bench --quick --docs ") < page.find("## Headline error and cost"));
  for (const std::string& s : scenes) {
    INFO(s);
    const std::size_t at = page.find("\n### " + s + " ");
    REQUIRE(at != std::string::npos);
    const std::size_t table = page.find("\n| setting | Hz | wall/sim | reps |", at);
    CHECK(table != std::string::npos);
    CHECK(table < page.find("\n### ", at + 1));
    CHECK(page.find("](" + s + ".png)", at) < table);
  }
  CHECK(page.find("## Piles") != std::string::npos);
}

TEST_CASE("tumble-bench -o writes the CSV and plots but no page") {
  const fs::path out = fs::path(TUMBLE_BINARY_DIR) / "bench-o";
  fs::remove_all(out);
  REQUIRE(runBench("--scenes S1 --settings tumble-rk4 --hz 60 --reps 1 -o " + out.string(), "bench-o.log") == 0);
  CHECK(fs::exists(out / "results.csv"));
  CHECK(fs::exists(out / "S1.png"));
  CHECK(!fs::exists(out / "results.md"));
  // The two are one choice: where everything goes.
  CHECK(runBench("--quick --docs " + out.string() + " -o " + out.string(), "bench-o-docs.log") != 0);
}
