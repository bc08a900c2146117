#include "plot/energy_inset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace tumble::plot {
namespace {

// The HUD's panel and text colours (app/overlay_text.cpp), and lines light enough for a dark panel.
constexpr Rgb kPanel{16, 18, 24}, kText{245, 245, 245}, kAxis{120, 124, 132};
constexpr double kPanelAlpha = 0.62;
constexpr Rgb kKinetic{255, 120, 90}, kPotential{100, 170, 255}, kTotal{245, 245, 245};

std::string joules(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g J", std::abs(v) < 5e-13 ? 0.0 : v);
  return buf;
}

}  // namespace

void drawEnergyInset(Canvas& c, double width, double height, double font_px, const EnergySeries& s,
                     std::size_t upto) {
  c.fillRect(0, 0, width, height, kPanel, kPanelAlpha);
  const Font font{font_px, false};
  const double pad = std::round(font_px * 0.45);
  const std::size_t n = std::min({upto, s.time.size(), s.kinetic.size(), s.potential.size()});
  std::vector<double> total(s.time.size());
  for (std::size_t i = 0; i < total.size(); ++i) total[i] = s.kinetic[i] + s.potential[i];

  // The top line: the key, and the total now.
  double x = pad;
  const double y_text = pad + font_px / 2;
  for (const auto& [name, colour] : {std::pair{"K", kKinetic}, std::pair{"U", kPotential}, std::pair{"E", kTotal}}) {
    c.text(x, y_text, name, font, colour);
    x += c.textWidth(name, font) + pad;
  }
  if (n > 0) c.text(width - pad, y_text, "E " + joules(total[n - 1]), font, kText, Align::Right);

  // The plot area, below the top line; the range is the whole clip's, so the scale never jumps.
  const double left = pad, right = width - pad, top = 2 * pad + font_px, bottom = height - pad;
  if (s.time.size() < 2 || right - left < 4 || bottom - top < 4) return;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < s.time.size(); ++i)
    for (double v : {s.kinetic[i], s.potential[i], total[i]}) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(hi > lo)) hi = lo + 1;
  const double t0 = s.time.front(), t1 = s.time.back() > t0 ? s.time.back() : t0 + 1;
  auto px = [&](double t) { return left + (t - t0) / (t1 - t0) * (right - left); };
  auto py = [&](double e) { return bottom - (e - lo) / (hi - lo) * (bottom - top); };
  if (lo < 0 && hi > 0) c.line(left, py(0), right, py(0), kAxis, 1, true);   // zero, where it is in view
  c.line(left, bottom, right, bottom, kAxis, 1);
  const double line_w = std::max(1.0, font_px / 9);
  for (const auto& [values, colour] : {std::pair{&s.kinetic, kKinetic}, std::pair{&s.potential, kPotential},
                                       std::pair{static_cast<const std::vector<double>*>(&total), kTotal}}) {
    std::vector<std::pair<double, double>> points;
    points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) points.push_back({px(s.time[i]), py((*values)[i])});
    if (points.size() >= 2) c.polyline(points, colour, line_w);
    if (!points.empty()) c.marker(points.back().first, points.back().second, Marker::Circle, 1.5 * line_w, colour);
  }
}

}  // namespace tumble::plot
