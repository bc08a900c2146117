#include "app/overlay_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "plot/canvas.h"

namespace tumble {
namespace {

constexpr plot::Rgb kPanel{16, 18, 24}, kText{245, 245, 245};
constexpr double kPanelAlpha = 0.62;

plot::Rgb rgb(const Eigen::Vector3f& c) {
  return {static_cast<std::uint8_t>(std::lround(c.x() * 255)), static_cast<std::uint8_t>(std::lround(c.y() * 255)),
          static_cast<std::uint8_t>(std::lround(c.z() * 255))};
}

std::string format(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

// A figure to 4 significant digits, rounding noise below `floor` to 0 ("1.048e-21 J" of a body
// at rest is 0 J).
std::string figure(const char* f, double v, double floor) { return format(f, std::abs(v) < floor ? 0.0 : v); }

// "2 N", "0.5 N", "5000 N": a scale value of 1, 2 or 5 x 10^k.
std::string scaleText(double v, const char* unit) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g %s", v, unit);
  return buf;
}

// A line of text with an optional colour key (a short bar) before it.
struct Row {
  std::string text;
  bool keyed = false;
  plot::Rgb key{};
};

// Rows on a panel, drawn on a layer of the panel's own size, so that only its pixels are laid over
// the frame; its corner at (0, 0) until placed.
OverlayPanel panelLayer(const std::vector<Row>& rows, double font_px) {
  const plot::Font font{font_px, false};
  const double pad = std::round(font_px * 0.45), line = std::round(font_px * 1.3);
  const double key_w = std::round(font_px * 1.1);
  double width = 0;
  {
    plot::Canvas measure(plot::Canvas::Target::Layer, 1, 1);
    for (const Row& r : rows) width = std::max(width, measure.textWidth(r.text, font) + (r.keyed ? key_w + pad : 0));
  }
  const double height = line * static_cast<double>(rows.size()) + 2 * pad - (line - font_px);
  plot::Canvas c(plot::Canvas::Target::Layer, static_cast<int>(std::ceil(width + 2 * pad)), static_cast<int>(height));
  c.fillRect(0, 0, width + 2 * pad, height, kPanel, kPanelAlpha);
  double y = pad + font_px / 2;
  for (const Row& r : rows) {
    double x = pad;
    if (r.keyed) {
      c.fillRect(x, y - font_px * 0.2, x + key_w, y + font_px * 0.2, r.key, 1);
      x += key_w + pad;
    }
    c.text(x, y, r.text, font, kText);
    y += line;
  }
  return {c.layer(), 0, 0};
}

// The space between a panel and the frame's edge.
double panelMargin(double font_px) { return std::round(font_px * 0.4); }

// Rows on a panel whose top-left (or bottom-left, `from_bottom`) corner is the margin in from the
// frame's.
OverlayPanel panel(const std::vector<Row>& rows, double font_px, int frame_height, bool from_bottom) {
  OverlayPanel p = panelLayer(rows, font_px);
  const int margin = static_cast<int>(panelMargin(font_px));
  p.x = margin;
  p.y = from_bottom ? frame_height - margin - p.layer.height : margin;
  return p;
}

}  // namespace

double overlayFontPx(int frame_height) { return std::max(8.0, std::round(frame_height / 40.0)); }

OverlayPanel hudPanel(const HudFigures& h, int frame_height) {
  const double total = h.kinetic + h.potential, drift = total - h.start_total;
  // Energies below a billionth of the scene's are rounding: shown as 0.
  const double floor = 1e-9 * std::max({std::abs(h.start_total), std::abs(total), std::abs(h.kinetic), 1e-300});
  const double share = h.start_total != 0 ? 100 * drift / std::abs(h.start_total) : 0;
  std::vector<Row> rows;
  rows.push_back({format("t %.3f s", h.time_s) + "   frame " + std::to_string(h.frame) + "/" + std::to_string(h.frames)});
  rows.push_back({h.model + "   dt " + format("%.3g ms", 1e3 * h.dt_s)});
  rows.push_back({figure("E %.4g J", total, floor) + figure(" = K %.4g", h.kinetic, floor) +
                  figure(" + U %.4g", h.potential, floor)});
  rows.push_back({figure("drift %+.4g J", drift, floor) + figure(" (%+.3g %%)", std::abs(drift) < floor ? 0 : share, 1e-300)});
  const double deepest = h.deepest_m < 1e-12 ? 0 : h.deepest_m;   // below a picometre: rounding
  const std::string depth = deepest < 1e-4 ? format("%.3g \u00b5m", 1e6 * deepest) : format("%.3g mm", 1e3 * deepest);
  rows.push_back({"contacts " + std::to_string(h.contacts) + "   deepest " + depth});
  return panel(rows, overlayFontPx(frame_height), frame_height, false);
}

OverlayPanel labelPanel(const std::string& text, double font_px, double x, double y) {
  OverlayPanel p = panelLayer({{text}}, font_px);
  // Up and to the right of the point, by half a line: beside the impact, not over it.
  p.x = static_cast<int>(std::lround(x + font_px * 0.5));
  p.y = static_cast<int>(std::lround(y - font_px * 0.5)) - p.layer.height;
  return p;
}

OverlayPanel textPanel(const std::vector<std::string>& lines, double font_px, int frame_height, bool from_bottom) {
  std::vector<Row> rows;
  for (const std::string& l : lines) rows.push_back({l});
  return panel(rows, font_px, frame_height, from_bottom);
}

std::optional<OverlayPanel> legendPanel(const OverlaySpec& spec, const OverlayScales& s, int frame_height) {
  using namespace overlay_colour;
  std::vector<Row> rows;
  if (spec.has(OverlayKind::Contacts)) {
    rows.push_back({"resting, sticking", true, rgb(kResting)});
    rows.push_back({"resting, sliding", true, rgb(kSliding)});
    rows.push_back({"colliding", true, rgb(kColliding)});
    rows.push_back({"separating", true, rgb(kSeparating)});
  }
  if (spec.has(OverlayKind::Forces)) {
    rows.push_back({"force: 1 m = " + scaleText(s.force_n_per_m, "N"), true, rgb(kForce)});
    if (s.impacts) rows.push_back({"impulse: 1 m = " + scaleText(s.impulse_ns_per_m, "N s"), true, rgb(kImpulse)});
  }
  if (spec.has(OverlayKind::Velocities))
    rows.push_back({"velocity: 1 m = " + scaleText(1 / s.speed_s, "m/s"), true, rgb(kVelocity)});
  if (spec.has(OverlayKind::BackStep)) {
    rows.push_back({"back-step trial: apart", true, rgb(kTrialApart)});
    rows.push_back({"back-step trial: too deep", true, rgb(kTrialDeep)});
    rows.push_back({"first contact found", true, rgb(kFirstContact)});
  }
  if (spec.has(OverlayKind::BroadPhase)) {
    rows.push_back({"piece's box (AABB)", true, rgb(kBox)});
    rows.push_back({"broad-phase pair", true, rgb(kPair)});
  }
  if (rows.empty()) return std::nullopt;
  return panel(rows, overlayFontPx(frame_height), frame_height, true);
}

}  // namespace tumble
