// The benchmark's outputs: a table per scene on stdout, one CSV of every metric, a plot per scene.
// The markdown page (results_page.h) shows the same tables, built once here.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_scene.h"
#include "bench/run_point.h"

namespace tumble::bench {

struct SceneResults {
  BenchScene scene;
  std::vector<RunResult> rows;
  std::vector<std::string> skipped;   // "ode-step: dense LCP far too slow at N >= 300"
};

// One scene's table as text cells: setting, Hz, wall/sim, reps, MB (piles), each metric, note.
struct SceneTable {
  std::string caption;                      // "S1 cube drop (2 s; headline error apex_err)"
  std::vector<std::string> head;
  std::vector<std::size_t> widths;          // columns' widths on stdout (the note is not padded)
  std::vector<std::vector<std::string>> rows;
};

SceneTable sceneTable(const SceneResults& s);
// How a figure is shown in the tables: "-" for NaN, integers plain, else 3 significant digits.
std::string formatFigure(double x);

void printTable(std::ostream& out, const SceneResults& s);
// What did not run in full, one line each: "S6_100 tumble-rk4 1/240: cut at 1.6 s of 5 s ...".
std::vector<std::string> cutLines(const std::vector<SceneResults>& all);
// Long format, one metric per line: scene,setting,engine,dt_s,hz,wall_s_per_sim_s,reps,
// simulated_s,cut,peak_rss_mb,failed,metric,value,headline,note.
void writeCsv(const std::filesystem::path& file, const std::vector<SceneResults>& all);
// The scene's plot as `file` (PNG) and, beside it, the same drawing as SVG (FILE with .svg).
void writePlot(const std::filesystem::path& file, const SceneResults& s);

}  // namespace tumble::bench
