// The results CSV read back as tumble-bench --plot-from reads it: what writeCsv wrote, row for row.
#include <catch2/catch.hpp>
#include <filesystem>
#include <sstream>

#include "bench/results_csv.h"
#include "bench/scene_plot.h"
#include "bench_test_support.h"

using namespace tumble::bench;
using testing::madeUpRow;

TEST_CASE("a results CSV reads back to the scenes, points and metrics that were written") {
  SceneResults drop{makeScene("S1", {1.0 / 60, 1.0 / 240}), {}, {}};
  drop.rows = {madeUpRow("S1", "tumble-rk4", 1.0 / 60, 1.2e-4, {{"apex_err", 1.8e-4}, {"e_eff", 0.4998}}),
               madeUpRow("S1", "tumble-rk4", 1.0 / 240, 4.4e-4, {{"apex_err", 1.8e-5}, {"e_eff", 0.49999}}),
               madeUpRow("S1", "bullet", 1.0 / 60, 8.9e-5, {{"apex_err", 0.17}})};
  drop.rows.back().note = "a \"quoted\", comma'd note";
  drop.rows.back().cut = true;
  SceneResults pile{makeScene("S6_100", {}), {}, {}};
  pile.rows = {madeUpRow("S6_100", "tumble-ts", 1.0 / 240, 3.1, {{"sc_err", 0.1}}), madeUpRow("S6_100", "ode-step", 1.0 / 240, 9, {})};
  pile.rows.back().failed = true;
  const std::filesystem::path file = std::filesystem::path(TUMBLE_BINARY_DIR) / "results-roundtrip.csv";
  writeCsv(file, {drop, pile});

  const std::vector<SceneResults> back = readResultsCsv(file);
  REQUIRE(back.size() == 2);
  CHECK(back[0].scene.id == "S1");
  CHECK(back[0].scene.title == "cube drop");
  CHECK(back[0].scene.dts.size() == 2);
  CHECK(back[1].scene.id == "S6_100");
  REQUIRE(back[0].rows.size() == 3);
  REQUIRE(back[1].rows.size() == 2);
  const RunResult& b = back[0].rows[2];
  CHECK(b.setting == "bullet");
  CHECK(b.engine == "bullet");
  CHECK(b.dt == Approx(1.0 / 60).epsilon(1e-8));
  CHECK(b.wall_per_sim == Approx(8.9e-5).epsilon(1e-8));
  CHECK(b.cut);
  CHECK(b.note == "a \"quoted\", comma'd note");
  CHECK(metricValue(back[0].rows[1], "apex_err") == Approx(1.8e-5).epsilon(1e-8));
  CHECK(metricValue(back[0].rows[1], "e_eff") == Approx(0.49999).epsilon(1e-8));
  CHECK(back[0].rows[0].metrics.size() == 2);
  CHECK(back[1].rows[1].failed);
  CHECK(back[1].rows[1].metrics.empty());
}

TEST_CASE("a malformed results CSV is refused with its line") {
  const std::string head = "scene,setting,engine,dt_s,hz,wall_s_per_sim_s,reps,simulated_s,cut,peak_rss_mb,failed,"
                           "metric,value,headline,note\n";
  std::istringstream short_row(head + "S1,tumble-rk4,tumble,0.0166666667,60\n");
  CHECK_THROWS_WITH(readResultsCsv(short_row, "r.csv"), Catch::Contains("r.csv:2: 5 fields"));
  std::istringstream bad_number(head + "S1,tumble-rk4,tumble,x,60,1,3,2,0,5,0,apex_err,1,1,\n");
  CHECK_THROWS_WITH(readResultsCsv(bad_number, "r.csv"), Catch::Contains("r.csv:2:"));
  std::istringstream unknown(head + "S99,tumble-rk4,tumble,0.01,100,1,3,2,0,5,0,apex_err,1,1,\n");
  CHECK_THROWS_WITH(readResultsCsv(unknown, "r.csv"), Catch::Contains("S99"));
  std::istringstream no_header("S1,tumble-rk4\n");
  CHECK_THROWS_WITH(readResultsCsv(no_header, "r.csv"), Catch::Contains("not a tumble-bench results CSV"));
}
