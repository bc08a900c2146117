#include "bench/results_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "bench/metrics.h"
#include "bench/scene_plot.h"

namespace tumble::bench {
namespace {

// A table cell: a '|' would end the cell early.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void tableRow(std::ostream& out, const std::vector<std::string>& cells) {
  out << "|";
  for (const std::string& c : cells) out << " " << cell(c) << " |";
  out << "\n";
}

void tableHead(std::ostream& out, const std::vector<std::string>& head) {
  tableRow(out, head);
  out << "|";
  for (std::size_t i = 0; i < head.size(); ++i) out << "---|";
  out << "\n";
}

long hzOf(double dt) { return std::lround(1 / dt); }

std::string minutes(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 600 ? "%.1f min" : "%.0f min", s / 60);
  return buf;
}

void writeStamp(std::ostream& out, const RunStamp& stamp, const PageProgress& progress, std::size_t done) {
  std::string engines;
  for (const std::string& e : stamp.engines) engines += (engines.empty() ? "" : ", ") + e;
  const std::string run = done < progress.scenes_planned
                              ? "partial: " + std::to_string(done) + " of " + std::to_string(progress.scenes_planned) +
                                    " scenes after " + minutes(progress.elapsed_s)
                              : minutes(progress.elapsed_s) + ", all " + std::to_string(done) + " scenes";
  out << "| | |\n|---|---|\n";
  tableRow(out, {"command", "`" + stamp.command + "`"});
  tableRow(out, {"date", stamp.date});
  tableRow(out, {"commit", stamp.commit});
  tableRow(out, {"build type", stamp.build_type});
  tableRow(out, {"machine", stamp.machine.cpu_model + ", " + std::to_string(stamp.machine.cores) + " cores"});
  tableRow(out, {"engines", engines});
  tableRow(out, {"run time", run});
  tableRow(out, {"every figure", "[results.csv](results.csv), one metric per line"});
}

// Per dt, one row per non-pile scene: its headline error and cost under each setting.
void writeSummary(std::ostream& out, const std::vector<SceneResults>& all) {
  std::vector<long> rates;
  std::vector<std::string> settings;
  for (const SceneResults& s : all) {
    if (s.scene.kind == SceneKind::Pile) continue;
    for (const RunResult& r : s.rows) {
      if (std::find(rates.begin(), rates.end(), hzOf(r.dt)) == rates.end()) rates.push_back(hzOf(r.dt));
      if (std::find(settings.begin(), settings.end(), r.setting) == settings.end()) settings.push_back(r.setting);
    }
  }
  if (rates.empty()) return;
  std::sort(rates.begin(), rates.end());
  out << "\n## Headline error and cost\n\nEach cell is *headline error / wall s per simulated s* of one "
         "setting at one dt; \"–\" where the setting did not run. The errors are defined in "
         "[scenes.md](scenes.md).\n";
  for (long hz : rates) {
    out << "\n### dt = 1/" << hz << " s\n\n";
    std::vector<std::string> head{"scene (error)"};
    head.insert(head.end(), settings.begin(), settings.end());
    tableHead(out, head);
    for (const SceneResults& s : all) {
      if (s.scene.kind == SceneKind::Pile) continue;
      const std::string metric = headlineMetric(s.scene.kind);
      std::vector<std::string> row{s.scene.id + " (" + metric + ")"};
      for (const std::string& name : settings) {
        auto it = std::find_if(s.rows.begin(), s.rows.end(),
                               [&](const RunResult& r) { return r.setting == name && hzOf(r.dt) == hz; });
        row.push_back(it == s.rows.end() || it->failed
                          ? "–"
                          : formatFigure(metricValue(*it, metric)) + " / " + formatFigure(it->wall_per_sim));
      }
      tableRow(out, row);
    }
  }
}

// The piles side by side: every engine timed over the same head of the fall where one was cut.
void writePiles(std::ostream& out, const std::vector<SceneResults>& all) {
  bool any = false;
  for (const SceneResults& s : all) any = any || (s.scene.kind == SceneKind::Pile && !s.rows.empty());
  if (!any) return;
  out << "\n## Piles\n\nWall s per simulated s over the whole run and over its first *head* seconds (the "
         "stretch the earliest cut run reached, on which every engine is timed again); penetration "
         "and escapes at the end of each run; sc_err against the same engine at dt/4 up to the "
         "horizon; peak resident memory of the run's process.\n\n";
  tableHead(out, {"pile", "setting", "Hz", "wall/sim", "simulated s", "head s", "wall/sim over head",
                  "max_pen_end m", "escaped", "sc_err m", "horizon s", "MB"});
  for (const SceneResults& s : all) {
    if (s.scene.kind != SceneKind::Pile) continue;
    for (const RunResult& r : s.rows)
      tableRow(out, {s.scene.id, r.setting, std::to_string(hzOf(r.dt)), formatFigure(r.wall_per_sim),
                     formatFigure(r.simulated_s), formatFigure(metricValue(r, "head_s")),
                     formatFigure(metricValue(r, "wall_per_sim_head")), formatFigure(metricValue(r, "max_pen_end")),
                     formatFigure(metricValue(r, "escaped")), formatFigure(metricValue(r, "sc_err")),
                     formatFigure(metricValue(r, "sc_horizon_s")), formatFigure(r.peak_rss_mb)});
  }
}

void writeScene(std::ostream& out, const SceneResults& s) {
  const SceneTable t = sceneTable(s);
  out << "\n### " << t.caption << "\n\n![" << s.scene.id << " " << s.scene.title << "](" << s.scene.id
      << ".png)\n\n";
  tableHead(out, t.head);
  for (const std::vector<std::string>& row : t.rows) tableRow(out, row);
  for (const std::string& k : s.skipped) out << "\nSkipped " << cell(k) << "\n";
}

}  // namespace

void writeResultsPage(std::ostream& out, const RunStamp& stamp, const PageProgress& progress,
                      const std::vector<SceneResults>& all) {
  out << "# Benchmark results\n\nWritten by `tumble-bench` from the run it measured; the command below "
         "regenerates this page, the plots and the CSV. The scenes, their metrics and how the time is "
         "taken: [scenes.md](scenes.md); how each peer engine is set up: [peers.md](peers.md). Wall "
         "times come from a machine shared with other work: compare ratios within this page rather "
         "than absolute times across machines.\n\n";
  writeStamp(out, stamp, progress, all.size());
  writeSummary(out, all);
  writePiles(out, all);
  out << "\n## Scenes\n\nx = wall s per simulated s, y = the headline error, both log scale; one line per "
         "setting through its dt values, the big dot at the largest dt; exact answers sit on the "
         "dashed \"0\" line.\n";
  for (const SceneResults& s : all) writeScene(out, s);
  out << "\n## Cut, skipped or failed\n\n";
  const std::vector<std::string> cuts = cutLines(all);
  for (const std::string& c : cuts) out << "- " << cell(c) << "\n";
  if (cuts.empty()) out << "Nothing.\n";
}

void writeResultsPage(const std::filesystem::path& file, const RunStamp& stamp, const PageProgress& progress,
                      const std::vector<SceneResults>& all) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  writeResultsPage(out, stamp, progress, all);
  if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace tumble::bench
