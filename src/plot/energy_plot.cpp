#include "plot/energy_plot.h"

#include <algorithm>
#include <limits>

#include "plot/linear_axis.h"

namespace tumble::plot {
namespace {

constexpr double kLeft = 96, kRight = 700, kTop = 50, kBottom = 470;   // px: the plot area
constexpr double kLegendX = 724;
constexpr Rgb kInk{25, 25, 25}, kGrid{225, 225, 225};
constexpr Rgb kKinetic{200, 60, 40}, kPotential{40, 100, 190}, kTotal{25, 25, 25};
constexpr Font kTitleFont{18, true}, kAxisFont{13, false}, kTickFont{13, false}, kLegendFont{13, false};

struct Line {
  const char* name;
  Rgb colour;
  double width;
  std::vector<double> values;
};

}  // namespace

void drawEnergyPlot(Canvas& c, const EnergySeries& s) {
  std::vector<double> total(s.time.size());
  for (std::size_t i = 0; i < total.size(); ++i) total[i] = s.kinetic[i] + s.potential[i];
  const Line lines[] = {{"kinetic", kKinetic, 1.6, s.kinetic},
                        {"potential (gravity)", kPotential, 1.6, s.potential},
                        {"total", kTotal, 2.2, total}};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Line& l : lines)
    for (double v : l.values) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) lo = 0, hi = 1;
  const LinearAxis ax = linearAxis(s.time.empty() ? 0 : s.time.front(), s.time.empty() ? 1 : s.time.back(), 8);
  const LinearAxis ay = linearAxis(lo, hi, 7);
  auto px = [&](double t) { return kLeft + ax.fraction(t) * (kRight - kLeft); };
  auto py = [&](double e) { return kBottom - ay.fraction(e) * (kBottom - kTop); };

  for (double t : ax.ticks) c.line(px(t), kTop, px(t), kBottom, kGrid, 1);
  for (double e : ay.ticks) c.line(kLeft, py(e), kRight, py(e), kGrid, 1);
  for (double t : ax.ticks) {
    c.line(px(t), kBottom, px(t), kBottom + 6, kInk, 1);
    c.text(px(t), kBottom + 18, tickLabel(t, ax.step), kTickFont, kInk, Align::Centre);
  }
  for (double e : ay.ticks) {
    c.line(kLeft - 6, py(e), kLeft, py(e), kInk, 1);
    c.text(kLeft - 10, py(e), tickLabel(e, ay.step), kTickFont, kInk, Align::Right);
  }
  c.strokeRect(kLeft, kTop, kRight, kBottom, kInk, 1);
  c.text(kLeft, 24, s.title, kTitleFont, kInk);
  c.text((kLeft + kRight) / 2, kBottom + 44, "time (s)", kAxisFont, kInk, Align::Centre);
  c.text(26, (kTop + kBottom) / 2, "energy (J)", kAxisFont, kInk, Align::Centre, -90);

  double y = kTop + 8;
  for (const Line& l : lines) {
    std::vector<std::pair<double, double>> points;
    points.reserve(l.values.size());
    for (std::size_t i = 0; i < l.values.size(); ++i) points.push_back({px(s.time[i]), py(l.values[i])});
    c.polyline(points, l.colour, l.width);
    c.line(kLegendX, y, kLegendX + 26, y, l.colour, l.width);
    c.text(kLegendX + 34, y, l.name, kLegendFont, kInk);
    y += 20;
  }
  c.text(kLegendX, y + 8, "total = kinetic + potential", kLegendFont, kInk);
}

}  // namespace tumble::plot
