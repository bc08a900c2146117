#include "bench/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bench/metrics.h"
#include "bench/scene_plot.h"
#include "io/atomic_file.h"
#include "io/png_file.h"

namespace tumble::bench {
namespace {

std::string hz(double dt) { return std::to_string(std::lround(1 / dt)); }

std::string csvField(std::string s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Whole or not at all, as every output: a temporary sibling renamed when complete.
void writeTextFile(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temp = temporarySibling(file, "partial");
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::filesystem::remove(temp);
      throwCantWrite(file, "write failed");
    }
  }
  commitFile(temp, file, true);
}

std::string pad(const std::string& s, std::size_t w) { return s.size() >= w ? s + " " : s + std::string(w - s.size(), ' '); }

}  // namespace

std::string formatFigure(double x) {
  char buf[32];
  if (std::isnan(x)) return "-";
  if (x == std::round(x) && std::abs(x) < 1e6) std::snprintf(buf, sizeof buf, "%.0f", x);
  else std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

SceneTable sceneTable(const SceneResults& s) {
  const bool pile = s.scene.kind == SceneKind::Pile;
  SceneTable t;
  std::ostringstream caption;
  caption << s.scene.id << " " << s.scene.title << " (" << s.scene.duration << " s; headline error "
          << headlineMetric(s.scene.kind) << ")";
  t.caption = caption.str();
  std::vector<std::string> names;
  for (const RunResult& r : s.rows)
    for (const Metric& m : r.metrics)
      if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
  t.head = {"setting", "Hz", "wall/sim", "reps"};
  t.widths = {20, 6, 10, 5};
  if (pile) {
    t.head.push_back("MB");
    t.widths.push_back(6);
  }
  for (const std::string& n : names) {
    t.head.push_back(n);
    t.widths.push_back(std::max<std::size_t>(10, n.size() + 1));
  }
  t.head.push_back("note");
  for (const RunResult& r : s.rows) {
    std::vector<std::string> row = {r.setting, hz(r.dt), formatFigure(r.wall_per_sim), std::to_string(r.reps)};
    if (pile) row.push_back(formatFigure(r.peak_rss_mb));
    for (const std::string& n : names) row.push_back(formatFigure(metricValue(r, n)));
    row.push_back(r.note);
    t.rows.push_back(std::move(row));
  }
  return t;
}

void printTable(std::ostream& out, const SceneResults& s) {
  const SceneTable t = sceneTable(s);
  out << "\n" << t.caption << "\n";
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < t.widths.size(); ++i) out << pad(cells[i], t.widths[i]);
    out << cells.back() << "\n";
  };
  line(t.head);
  for (const std::vector<std::string>& row : t.rows) line(row);
  for (const std::string& k : s.skipped) out << "  skipped " << k << "\n";
}

std::vector<std::string> cutLines(const std::vector<SceneResults>& all) {
  std::vector<std::string> out;
  for (const SceneResults& s : all) {
    for (const RunResult& r : s.rows)
      if (r.cut || r.failed) out.push_back(r.scene + " " + r.setting + " 1/" + hz(r.dt) + ": " + r.note);
    for (const std::string& k : s.skipped) out.push_back(s.scene.id + " " + k);
  }
  return out;
}

void writeCsv(const std::filesystem::path& file, const std::vector<SceneResults>& all) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("tumble-bench: cannot write " + file.string());
  out << "scene,setting,engine,dt_s,hz,wall_s_per_sim_s,reps,simulated_s,cut,peak_rss_mb,failed,metric,value,headline,note\n";
  char buf[64];
  auto num = [&](double x) { std::snprintf(buf, sizeof buf, "%.9g", x); return std::string(buf); };
  for (const SceneResults& s : all) {
    const std::string headline = headlineMetric(s.scene.kind);
    for (const RunResult& r : s.rows) {
      const std::string common = r.scene + "," + r.setting + "," + r.engine + "," + num(r.dt) + "," + hz(r.dt) + "," +
                                 num(r.wall_per_sim) + "," + std::to_string(r.reps) + "," + num(r.simulated_s) + "," +
                                 (r.cut ? "1" : "0") + "," + num(r.peak_rss_mb) + "," + (r.failed ? "1" : "0") + ",";
      if (r.metrics.empty()) out << common << ",,," << csvField(r.note) << "\n";
      for (const Metric& m : r.metrics)
        out << common << m.name << "," << num(m.value) << "," << (m.name == headline ? "1" : "0") << ","
            << csvField(r.note) << "\n";
    }
  }
  if (!out.flush()) throw std::runtime_error("tumble-bench: cannot write " + file.string());
}

void writePlot(const std::filesystem::path& file, const SceneResults& s) {
  const PlotLabels labels{s.scene.id + " " + s.scene.title, headlineMetric(s.scene.kind),
                          headlineAxisTitle(s.scene.kind)};
  Canvas raster(Canvas::Target::Raster, kPlotWidth, kPlotHeight);
  drawScenePlot(raster, labels, s.rows);
  writePng(file, raster.image());
  Canvas vector(Canvas::Target::Svg, kPlotWidth, kPlotHeight);
  drawScenePlot(vector, labels, s.rows);
  writeTextFile(std::filesystem::path(file).replace_extension(".svg"), vector.finishSvg(labels.title));
}

}  // namespace tumble::bench
