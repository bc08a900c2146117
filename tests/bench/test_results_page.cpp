// The results page and its stamp, on made-up results: no simulation runs here.
#include <catch2/catch.hpp>
#include <sstream>

#include "bench/machine_info.h"
#include "bench/results_page.h"
#include "bench/run_stamp.h"
#include "bench_test_support.h"

using namespace tumble::bench;
using testing::madeUpRow;

namespace {

std::vector<SceneResults> twoScenes() {
  SceneResults drop{makeScene("S1", {1.0 / 60, 1.0 / 240}), {}, {}};
  drop.rows = {madeUpRow("S1", "tumble-rk4", 1.0 / 60, 1.2e-4, {{"apex_err", 1.8e-4}}),
               madeUpRow("S1", "tumble-rk4", 1.0 / 240, 4.4e-4, {{"apex_err", 1.8e-5}}),
               madeUpRow("S1", "bullet", 1.0 / 60, 8.9e-5, {{"apex_err", 0.17}})};
  drop.rows.back().note = "a | in a note";
  SceneResults pile{makeScene("S6_100", {}), {}, {"ode-step: far too slow"}};
  pile.rows = {madeUpRow("S6_100", "tumble-ts", 1.0 / 240, 3.1,
                   {{"max_pen_end", 9.5e-7}, {"escaped", 0}, {"head_s", 1.65}, {"wall_per_sim_head", 2.87},
                    {"sc_err", 0.1}, {"sc_horizon_s", 1}})};
  pile.rows[0].peak_rss_mb = 7;
  return {drop, pile};
}

RunStamp stamp() {
  RunStamp s;
  s.date = "2026-11-24 10:00 UTC";
  s.command = "tumble-bench --docs docs/bench";
  s.commit = "abc1234";
  s.build_type = "Release";
  s.machine = {"AMD EPYC", 2};
  s.engines = {"tumble 0.1.0", "Bullet 3.24"};
  return s;
}

}  // namespace

TEST_CASE("the machine comes from /proc/cpuinfo: the first model name, one core per processor") {
  std::istringstream in("processor\t: 0\nmodel name\t: AMD EPYC 7B13\nflags\t: fpu\n\n"
                        "processor\t: 1\nmodel name\t: AMD EPYC 7B13\n");
  const MachineInfo m = parseCpuinfo(in);
  CHECK(m.cpu_model == "AMD EPYC 7B13");
  CHECK(m.cores == 2);
  std::istringstream empty("");
  CHECK(parseCpuinfo(empty).cores == 0);
}

TEST_CASE("the command on the page can be pasted into a shell") {
  CHECK(shellQuoted("--hz") == "--hz");
  CHECK(shellQuoted("60,240") == "60,240");
  CHECK(shellQuoted("docs/my bench") == "'docs/my bench'");
  CHECK(shellQuoted("it's") == "'it'\\''s'");
  CHECK(shellQuoted("") == "''");
}

TEST_CASE("the results page: stamp, a summary per dt, the piles, a table per scene") {
  std::ostringstream out;
  writeResultsPage(out, stamp(), {2, 90}, twoScenes());
  const std::string page = out.str();
  CHECK(page.find("| command | `tumble-bench --docs docs/bench` |") != std::string::npos);
  CHECK(page.find("| commit | abc1234 |") != std::string::npos);
  CHECK(page.find("| machine | AMD EPYC, 2 cores |") != std::string::npos);
  CHECK(page.find("| engines | tumble 0.1.0, Bullet 3.24 |") != std::string::npos);
  CHECK(page.find("| run time | 1.5 min, all 2 scenes |") != std::string::npos);
  // Per dt: bullet ran only at 1/60 s.
  CHECK(page.find("### dt = 1/60 s") < page.find("### dt = 1/240 s"));
  CHECK(page.find("| S1 (apex_err) | 0.00018 / 0.00012 | 0.17 / 8.9e-05 |") != std::string::npos);
  CHECK(page.find("| S1 (apex_err) | 1.8e-05 / 0.00044 | – |") != std::string::npos);
  CHECK(page.find("| S6_100 | tumble-ts | 240 | 3.1 | 2 | 1.65 | 2.87 | 9.5e-07 | 0 | 0.1 | 1 | 7 |") !=
        std::string::npos);
  CHECK(page.find("![S1 cube drop](S1.png)") != std::string::npos);
  CHECK(page.find("a \\| in a note") != std::string::npos);
  CHECK(page.find("- S6_100 ode-step: far too slow") != std::string::npos);
}

TEST_CASE("a page written mid-run says it is partial") {
  std::ostringstream out;
  writeResultsPage(out, stamp(), {5, 600}, twoScenes());
  CHECK(out.str().find("| run time | partial: 2 of 5 scenes after 10 min |") != std::string::npos);
}
