// tumble-bench: speed against error on the benchmark scenes of docs/bench/scenes.md, tumble and
// the peers found at build time side by side in one run. See the README, "Speed against error".
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "bench/bench_options.h"
#include "bench/job_process.h"
#include "bench/report.h"
#include "bench/results_csv.h"
#include "bench/results_page.h"

namespace tb = tumble::bench;

namespace {

bool selected(const tb::BenchOptions& o, const tb::EngineSetting& s) {
  return o.settings.empty() || std::find(o.settings.begin(), o.settings.end(), s.name) != o.settings.end();
}

tb::SceneResults runScene(const tb::BenchScene& scene, const std::vector<tb::EngineSetting>& settings,
                          const tb::BenchOptions& o) {
  tb::SceneResults out{scene, {}, {}};
  tb::RunOptions run = o.run;
  for (const tb::EngineSetting& s : settings) {
    if (!selected(o, s)) continue;
    // A setting named on the command line runs even where it would be skipped by default.
    const std::string why = o.settings.empty() ? s.skip_reason(scene) : "";
    if (!why.empty()) {
      out.skipped.push_back(s.name + ": " + why);
      continue;
    }
    tb::BenchScene swept = scene;
    if (s.only_dt > 0 && o.settings.empty() && scene.dts.size() > 1) {
      const auto nearest = std::min_element(scene.dts.begin(), scene.dts.end(), [&](double a, double b) {
        return std::abs(std::log(a / s.only_dt)) < std::abs(std::log(b / s.only_dt));
      });
      swept.dts = {*nearest};
      out.skipped.push_back(s.name + ": runs at dt 1/" + std::to_string(std::lround(1 / *nearest)) + " s only: " +
                            s.only_dt_reason);
    }
    for (tb::RunResult& r : tb::runJobInChild(swept, s, run)) {
      // A pile cut short by the wall cap sets the horizon the later engines are also timed and
      // self-checked over, so that every engine is compared on the same stretch of the fall.
      if (r.cut && scene.kind == tb::SceneKind::Pile && (run.head_s == 0 || r.simulated_s < run.head_s)) {
        run.head_s = r.simulated_s;
        run.sc_horizon_s = std::min(run.sc_horizon_s, run.head_s);
      }
      // Likewise a reference run cut short: later engines are self-checked over the same horizon.
      if (scene.kind == tb::SceneKind::Pile)
        for (const tb::Metric& m : r.metrics)
          if (m.name == "sc_horizon_s" && m.value > 0) run.sc_horizon_s = std::min(run.sc_horizon_s, m.value);
      out.rows.push_back(std::move(r));
    }
  }
  return out;
}

// --plot-from: the plots of a finished run, redrawn from its CSV; nothing is simulated.
int plotFrom(const std::filesystem::path& csv, const std::filesystem::path& out_dir) {
  const std::vector<tb::SceneResults> all = tb::readResultsCsv(csv);
  std::filesystem::create_directories(out_dir);
  for (const tb::SceneResults& s : all) tb::writePlot(out_dir / (s.scene.id + ".png"), s);
  std::cout << "wrote " << all.size() << " plots (PNG and SVG) from " << csv.string() << " in "
            << out_dir.string() << "/\n";
  return 0;
}

// What did not run in full, in one place at the end of the report.
void printCuts(std::ostream& out, const std::vector<tb::SceneResults>& all) {
  out << "\nCut, skipped or failed:\n";
  const std::vector<std::string> lines = tb::cutLines(all);
  for (const std::string& l : lines) out << "  " << l << "\n";
  if (lines.empty()) out << "  nothing\n";
}

}  // namespace

int main(int argc, char** argv) {
  const auto started = std::chrono::steady_clock::now();
  const tb::RunStamp stamp_args = tb::stampThisRun({argv + 1, argv + argc});
  tb::BenchOptions o;
  bool list = false;
  std::filesystem::path docs_dir, plot_from;
  CLI::App app{"tumble-bench: wall time per simulated second against error, tumble and its peers"};
  app.add_flag("--quick", o.quick, "smoke test: dt 1/60 and 1/240, short durations, one run per point");
  app.add_option("--scenes", o.scenes, "scene ids (S1 S2a S2b S3 S4 S5 S6_100 S6_300 S6_1000 S6_10000 S7 S8 S8ccd)")->delimiter(',');
  app.add_option("--settings", o.settings, "engine settings to run (see --list); named ones run on every scene")->delimiter(',');
  app.add_option("--hz", o.hz, "steps per second to sweep (default 60,120,240,480,1000)")->delimiter(',');
  app.add_option("--reps", o.run.reps, "fresh runs per point; the median time is reported")->check(CLI::Range(1, 100));
  app.add_option("--cap", o.run.cap_s, "wall s of stepping after which a run stops early (reported as cut)")->check(CLI::PositiveNumber);
  app.add_option("--pile-duration", o.pile_duration_s, "simulated s of the piles (docs/bench/scenes.md: 5)")->check(CLI::PositiveNumber);
  app.add_option("--sc-horizon", o.run.sc_horizon_s, "horizon (s) of the piles' self-consistency error")->check(CLI::PositiveNumber);
  CLI::Option* out = app.add_option("-o,--out", o.out_dir, "folder for results.csv and the plots");
  app.add_option("--docs", docs_dir, "also write results.md (the tables, stamped with date, commit, "
                 "machine and engine versions) and put the CSV and plots beside it, e.g. docs/bench")
      ->excludes(out);
  app.add_option("--plot-from", plot_from, "draw the plots from a results.csv written before, running "
                 "nothing; they go beside the CSV, or into -o DIR")
      ->check(CLI::ExistingFile)
      ->excludes("--docs");
  app.add_flag("--list", list, "list the engine settings in this build and exit");
  CLI11_PARSE(app, argc, argv);
  if (o.quick) tb::applyQuick(o);
  if (!docs_dir.empty()) o.out_dir = docs_dir;

  const std::vector<tb::EngineSetting> settings = tb::availableSettings();
  if (list) {
    for (const tb::EngineSetting& s : settings) std::cout << s.name << "\n";
    return 0;
  }
  try {
    if (!plot_from.empty()) {
      const std::filesystem::path beside = plot_from.has_parent_path() ? plot_from.parent_path() : ".";
      return plotFrom(plot_from, out->count() ? o.out_dir : beside);
    }
    std::filesystem::create_directories(o.out_dir);
    tb::RunStamp stamp = stamp_args;
    stamp.engines = tb::engineVersions();
    const std::vector<tb::BenchScene> planned = tb::plannedScenes(o);
    std::vector<tb::SceneResults> all;
    for (const tb::BenchScene& scene : planned) {
      all.push_back(runScene(scene, settings, o));
      tb::printTable(std::cout, all.back());
      std::cout.flush();
      tb::writePlot(o.out_dir / (scene.id + ".png"), all.back());
      // Rewritten after each scene: a partial run keeps its data, and the page says it is partial.
      tb::writeCsv(o.out_dir / "results.csv", all);
      if (!docs_dir.empty()) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        tb::writeResultsPage(docs_dir / "results.md", stamp, {planned.size(), elapsed}, all);
      }
    }
    printCuts(std::cout, all);
    std::cout << "\nwrote " << (o.out_dir / "results.csv").string() << " and a plot per scene in "
              << o.out_dir.string() << "/\n";
    if (!docs_dir.empty()) std::cout << "wrote " << (docs_dir / "results.md").string() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "tumble-bench: " << e.what() << "\n";
    return 64;
  }
  return 0;
}
