#include "bench/scene_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "bench/canvas.h"

namespace tumble::bench {
namespace {

constexpr int kWidth = 760, kHeight = 460;
constexpr int kLeft = 64, kRight = 560, kTop = 36, kBottom = 400;   // the plot area
constexpr Rgb kWhite{255, 255, 255}, kInk{30, 30, 30}, kGrid{222, 222, 222};

// Colour per engine family, shade per setting within it: peers are told apart at a glance.
Rgb colourOf(const std::string& engine, int shade) {
  static const std::map<std::string, std::vector<Rgb>> palette = {
      {"tumble", {{200, 40, 30}, {240, 120, 40}, {150, 20, 90}, {230, 80, 150}}},
      {"bullet", {{30, 90, 200}, {90, 160, 235}, {20, 40, 120}}},
      {"ode", {{30, 150, 60}, {120, 200, 90}}},
      {"mujoco", {{120, 70, 170}, {170, 140, 210}}},
  };
  const auto it = palette.find(engine);
  if (it == palette.end()) return {90, 90, 90};
  return it->second[static_cast<std::size_t>(shade) % it->second.size()];
}

struct Series {
  std::string name, engine;
  std::vector<std::pair<double, double>> points;   // (x, y), ordered by decreasing dt
};

std::string decade(int e) { return "1E" + std::to_string(e); }

}  // namespace

double metricValue(const RunResult& r, const std::string& name) {
  for (const Metric& m : r.metrics)
    if (m.name == name) return m.value;
  return std::numeric_limits<double>::quiet_NaN();
}

RgbImage plotScene(const std::string& title, const std::string& metric,
                   const std::vector<RunResult>& results) {
  std::vector<Series> series;
  for (const RunResult& r : results) {
    const double x = r.wall_per_sim, y = metricValue(r, metric);
    if (r.failed || !std::isfinite(x) || x <= 0 || !std::isfinite(y)) continue;
    auto it = std::find_if(series.begin(), series.end(), [&](const Series& s) { return s.name == r.setting; });
    if (it == series.end()) it = series.insert(series.end(), Series{r.setting, r.engine, {}});
    it->points.push_back({x, std::abs(y)});
  }
  // Axis ranges in whole decades around the data.
  double xlo = 1e300, xhi = 1e-300, ylo = 1e300, yhi = 1e-300;
  bool any_zero = false;
  for (const Series& s : series)
    for (auto [x, y] : s.points) {
      xlo = std::min(xlo, x);
      xhi = std::max(xhi, x);
      if (y > 0) { ylo = std::min(ylo, y); yhi = std::max(yhi, y); } else any_zero = true;
    }
  if (xlo > xhi) { xlo = 1e-3; xhi = 1; }
  if (ylo > yhi) { ylo = 1e-3; yhi = 1; }
  const int ex0 = static_cast<int>(std::floor(std::log10(xlo))), ex1 = std::max(ex0 + 1, static_cast<int>(std::ceil(std::log10(xhi))));
  const int ey0 = static_cast<int>(std::floor(std::log10(ylo))), ey1 = std::max(ey0 + 1, static_cast<int>(std::ceil(std::log10(yhi))));
  // Exact zeros get their own row under the lowest decade.
  const int zero_row = kBottom - 12;
  const int y_axis_bottom = any_zero ? zero_row - 18 : kBottom;
  auto px = [&](double x) { return kLeft + static_cast<int>(std::lround((std::log10(x) - ex0) / (ex1 - ex0) * (kRight - kLeft))); };
  auto py = [&](double y) {
    if (y <= 0) return zero_row;
    return y_axis_bottom - static_cast<int>(std::lround((std::log10(y) - ey0) / (ey1 - ey0) * (y_axis_bottom - kTop)));
  };

  Canvas c(kWidth, kHeight, kWhite);
  for (int e = ex0; e <= ex1; ++e) {
    c.line(px(std::pow(10.0, e)), kTop, px(std::pow(10.0, e)), kBottom, kGrid);
    c.text(px(std::pow(10.0, e)) - Canvas::textWidth(decade(e)) / 2, kBottom + 6, decade(e), kInk);
  }
  const int ystep = (ey1 - ey0) > 10 ? 2 : 1;
  for (int e = ey0; e <= ey1; e += ystep) {
    c.line(kLeft, py(std::pow(10.0, e)), kRight, py(std::pow(10.0, e)), kGrid);
    c.text(kLeft - 6 - Canvas::textWidth(decade(e)), py(std::pow(10.0, e)) - 3, decade(e), kInk);
  }
  if (any_zero) {
    c.dashedHLine(kLeft, kRight, zero_row, kInk);
    c.text(kLeft - 12, zero_row - 3, "0", kInk);
  }
  c.line(kLeft, kTop, kLeft, kBottom, kInk);
  c.line(kLeft, kBottom, kRight, kBottom, kInk);
  c.text(kLeft, 8, title, kInk, 2);
  c.text((kLeft + kRight) / 2 - Canvas::textWidth("WALL S PER SIMULATED S") / 2, kBottom + 22, "wall s per simulated s", kInk);
  c.text(kLeft, kTop - 12, metric, kInk);

  std::map<std::string, int> shades;
  int legend_y = kTop;
  for (const Series& s : series) {
    const Rgb col = colourOf(s.engine, shades[s.engine]++);
    for (std::size_t i = 0; i + 1 < s.points.size(); ++i)
      c.line(px(s.points[i].first), py(s.points[i].second), px(s.points[i + 1].first), py(s.points[i + 1].second), col, 2);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const int r = i == 0 ? 4 : 2;   // the largest dt gets the big dot
      c.fillRect(px(s.points[i].first) - r, py(s.points[i].second) - r, px(s.points[i].first) + r, py(s.points[i].second) + r, col);
    }
    c.fillRect(kRight + 16, legend_y, kRight + 28, legend_y + 6, col);
    c.text(kRight + 34, legend_y, s.name, kInk);
    legend_y += 14;
  }
  c.text(kRight + 16, legend_y + 8, "big dot: largest dt", kInk);
  return c.image();
}

}  // namespace tumble::bench
