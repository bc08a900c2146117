#include "bench/scene_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "bench/log_axis.h"

namespace tumble::bench {
namespace {

constexpr double kLeft = 100, kRight = 690, kTop = 50, kBottom = 530;   // px: the plot area
constexpr double kLegendX = 712;
constexpr Rgb kInk{25, 25, 25}, kMuted{90, 90, 90}, kGrid{225, 225, 225}, kMinorGrid{243, 243, 243};
constexpr Font kTitleFont{18, true}, kAxisFont{13, false}, kTickFont{13, false}, kLegendFont{12, false};

struct Series {
  std::string name;
  SeriesStyle style;
  std::vector<std::pair<double, double>> points;   // (x, y), ordered by decreasing dt
};

std::vector<Series> collectSeries(const std::string& metric, const std::vector<RunResult>& results) {
  std::vector<Series> series;
  std::map<Family, int> in_family;
  for (const RunResult& r : results) {
    const double x = r.wall_per_sim, y = metricValue(r, metric);
    if (r.failed || !std::isfinite(x) || x <= 0 || !std::isfinite(y)) continue;
    auto it = std::find_if(series.begin(), series.end(), [&](const Series& s) { return s.name == r.setting; });
    if (it == series.end()) {
      const Family f = familyOf(r.setting, r.engine);
      it = series.insert(series.end(), Series{r.setting, seriesStyle(f, in_family[f]++), {}});
    }
    it->points.push_back({x, std::abs(y)});
  }
  return series;
}

// The axes' ranges over the data; exact zeros on y get their own row and are left out here.
struct Ranges {
  double xlo = std::numeric_limits<double>::infinity(), xhi = 0;
  double ylo = std::numeric_limits<double>::infinity(), yhi = 0;
  bool any_zero = false;
};

Ranges rangesOf(const std::vector<Series>& series) {
  Ranges r;
  for (const Series& s : series)
    for (auto [x, y] : s.points) {
      r.xlo = std::min(r.xlo, x);
      r.xhi = std::max(r.xhi, x);
      if (y > 0) {
        r.ylo = std::min(r.ylo, y);
        r.yhi = std::max(r.yhi, y);
      } else {
        r.any_zero = true;
      }
    }
  if (r.xlo > r.xhi) { r.xlo = 1e-3; r.xhi = 1; }
  if (r.ylo > r.yhi) { r.ylo = 1e-3; r.yhi = 1; }
  return r;
}

void drawAxes(Canvas& c, const LogAxis& ax, const LogAxis& ay, double y_log_bottom) {
  auto px = [&](double v) { return kLeft + ax.fraction(v) * (kRight - kLeft); };
  auto py = [&](double v) { return y_log_bottom - ay.fraction(v) * (y_log_bottom - kTop); };
  // Grid first, so that ticks and data lie on top of it.
  for (double v : ax.minors) c.line(px(v), kTop, px(v), kBottom, kMinorGrid, 1);
  for (double v : ay.minors) c.line(kLeft, py(v), kRight, py(v), kMinorGrid, 1);
  for (int e : ax.majors) c.line(px(std::pow(10.0, e)), kTop, px(std::pow(10.0, e)), kBottom, kGrid, 1);
  for (int e : ay.majors) c.line(kLeft, py(std::pow(10.0, e)), kRight, py(std::pow(10.0, e)), kGrid, 1);
  // Ticks outside the frame: 7 px at decades, 4 px at the minor ticks.
  for (double v : ax.minors) c.line(px(v), kBottom, px(v), kBottom + 4, kInk, 1);
  for (double v : ay.minors) c.line(kLeft - 4, py(v), kLeft, py(v), kInk, 1);
  for (int e : ax.majors) {
    const double x = px(std::pow(10.0, e));
    c.line(x, kBottom, x, kBottom + 7, kInk, 1);
    if (ax.labelled(e)) c.text(x, kBottom + 18, decadeLabel(e), kTickFont, kInk, Align::Centre);
  }
  for (const auto& [v, label] : ax.minor_labels) c.text(px(v), kBottom + 18, label, kTickFont, kMuted, Align::Centre);
  for (const auto& [v, label] : ay.minor_labels) c.text(kLeft - 10, py(v), label, kTickFont, kMuted, Align::Right);
  for (int e : ay.majors) {
    const double y = py(std::pow(10.0, e));
    c.line(kLeft - 7, y, kLeft, y, kInk, 1);
    if (ay.labelled(e)) c.text(kLeft - 10, y, decadeLabel(e), kTickFont, kInk, Align::Right);
  }
  c.strokeRect(kLeft, kTop, kRight, kBottom, kInk, 1);
}

void drawLegend(Canvas& c, const std::vector<Series>& series, bool any_zero) {
  double y = kTop + 6;
  for (const Series& s : series) {
    c.line(kLegendX, y, kLegendX + 24, y, s.style.colour, s.style.line_width);
    c.marker(kLegendX + 12, y, s.style.marker, 4, s.style.colour);
    c.text(kLegendX + 32, y, s.name, kLegendFont, kInk);
    y += 17;
  }
  y += 8;
  c.marker(kLegendX + 12, y, Marker::Circle, 6, kMuted);
  c.text(kLegendX + 32, y, "largest dt of a setting", kLegendFont, kMuted);
  if (any_zero) c.text(kLegendX, y + 18, "0: exact answer (error 0)", kLegendFont, kMuted);
}

}  // namespace

double metricValue(const RunResult& r, const std::string& name) {
  for (const Metric& m : r.metrics)
    if (m.name == name) return m.value;
  return std::numeric_limits<double>::quiet_NaN();
}

void drawScenePlot(Canvas& c, const PlotLabels& labels, const std::vector<RunResult>& results) {
  const std::vector<Series> series = collectSeries(labels.metric, results);
  const Ranges r = rangesOf(series);
  const LogAxis ax = logAxis(r.xlo, r.xhi), ay = logAxis(r.ylo, r.yhi);
  // Exact zeros cannot sit on a log axis: they get a dashed row under it, below a gap.
  const double zero_row = kBottom - 12;
  const double y_log_bottom = r.any_zero ? kBottom - 36 : kBottom;
  auto px = [&](double x) { return kLeft + ax.fraction(x) * (kRight - kLeft); };
  auto py = [&](double y) { return y <= 0 ? zero_row : y_log_bottom - ay.fraction(y) * (y_log_bottom - kTop); };

  drawAxes(c, ax, ay, y_log_bottom);
  if (r.any_zero) {
    c.line(kLeft, zero_row, kRight, zero_row, kMuted, 1, true);
    c.text(kLeft - 10, zero_row, "0", kTickFont, kInk, Align::Right);
  }
  c.text(kLeft, 24, labels.title, kTitleFont, kInk);
  c.text((kLeft + kRight) / 2, kBottom + 44, "wall time per simulated second (s/s)", kAxisFont, kInk, Align::Centre);
  c.text(28, (kTop + kBottom) / 2, labels.y_title, kAxisFont, kInk, Align::Centre, -90);

  for (const Series& s : series) {
    std::vector<std::pair<double, double>> line;
    for (auto [x, y] : s.points) line.push_back({px(x), py(y)});
    c.polyline(line, s.style.colour, s.style.line_width);
    const double broader = s.style.line_width / 2 - 0.8;   // markers grow with the line
    for (std::size_t i = 0; i < line.size(); ++i)   // the largest dt, first, gets the big marker
      c.marker(line[i].first, line[i].second, s.style.marker, (i == 0 ? 6 : 3.5) + broader, s.style.colour);
  }
  drawLegend(c, series, r.any_zero);
}

}  // namespace tumble::bench
