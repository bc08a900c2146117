// The benchmark's outputs: a table per scene on stdout, one CSV of every metric, a plot per scene.
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

void printTable(std::ostream& out, const SceneResults& s);
// Long format, one metric per line: scene,setting,engine,dt_s,hz,wall_s_per_sim_s,reps,
// simulated_s,cut,peak_rss_mb,failed,metric,value,headline,note.
void writeCsv(const std::filesystem::path& file, const std::vector<SceneResults>& all);
void writePlot(const std::filesystem::path& file, const SceneResults& s);

}  // namespace tumble::bench
