#include "plot/canvas.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace tumble::plot {
namespace {

cairo_status_t appendTo(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

std::string xmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// cairo names the SVG's groups "surfaceN" after a counter shared by every surface the process has
// made, so the same plot would read "surface128" after other plots and "surface1" alone. Numbered
// again in order of appearance, the document depends on its drawing only.
std::string renumberSurfaceIds(const std::string& svg) {
  static const std::string kPrefix = "surface";
  std::vector<std::string> seen;
  std::string out;
  std::size_t at = 0;
  for (std::size_t hit = svg.find(kPrefix); hit != std::string::npos; hit = svg.find(kPrefix, at)) {
    std::size_t end = hit + kPrefix.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    out.append(svg, at, end - at);
    at = end;
    if (end == hit + kPrefix.size()) continue;   // "surface" not followed by a number
    const std::string id = svg.substr(hit + kPrefix.size(), end - hit - kPrefix.size());
    auto it = std::find(seen.begin(), seen.end(), id);
    if (it == seen.end()) it = seen.insert(seen.end(), id);
    out.replace(out.size() - id.size(), id.size(), std::to_string(it - seen.begin() + 1));
  }
  return out + svg.substr(at);
}

// An image surface's pixels as cairo keeps them, native-endian 32-bit 0xAARRGGBB (RGB24 leaves the
// top byte unused; ARGB32 premultiplies the colour), unpacked into R, G, B (and A, for 4 channels).
void unpackPixels(cairo_surface_t* surface, int channels, int& width, int& height, std::vector<std::uint8_t>& out) {
  cairo_surface_flush(surface);
  width = cairo_image_surface_get_width(surface);
  height = cairo_image_surface_get_height(surface);
  out.resize(static_cast<std::size_t>(width) * height * channels);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &out[(static_cast<std::size_t>(y) * width + x) * channels];
      p[0] = static_cast<std::uint8_t>(row[x] >> 16);
      p[1] = static_cast<std::uint8_t>(row[x] >> 8);
      p[2] = static_cast<std::uint8_t>(row[x]);
      if (channels == 4) p[3] = static_cast<std::uint8_t>(row[x] >> 24);
    }
  }
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

}  // namespace

Canvas::Canvas(Target target, int width, int height) : target_(target) {
  if (target == Target::Raster) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  } else if (target == Target::Layer) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);   // zeroed: transparent
  } else {
    surface_ = cairo_svg_surface_create_for_stream(appendTo, &svg_, width, height);
    // Pixels, as the PNG: cairo's default unit, pt, would show the SVG a third larger.
    cairo_svg_surface_set_document_unit(surface_, CAIRO_SVG_UNIT_PX);
  }
  cr_ = cairo_create(surface_);
  if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(cairo_status(cr_)));
  // Explicit font rendering, not the desktop's fontconfig preferences: the same data must give
  // the same PNG bytes on any machine with the same cairo and DejaVu fonts.
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_SLIGHT);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr_, options);
  cairo_font_options_destroy(options);
  if (target == Target::Layer) return;
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void Canvas::setSource(Rgb c) { cairo_set_source_rgb(cr_, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0); }

void Canvas::useFont(Font f) {
  cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         f.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, f.size);
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) {
  const double dash[] = {4, 3};   // px on, px off
  cairo_set_dash(cr_, dash, dashed ? 2 : 0, 0);
  polyline({{x0, y0}, {x1, y1}}, c, width);
  cairo_set_dash(cr_, nullptr, 0, 0);
}

void Canvas::polyline(const std::vector<std::pair<double, double>>& points, Rgb c, double width) {
  if (points.empty()) return;
  cairo_move_to(cr_, points[0].first, points[0].second);
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i].first, points[i].second);
  setSource(c);
  cairo_set_line_width(cr_, width);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr_);
}

void Canvas::strokeRect(double x0, double y0, double x1, double y1, Rgb c, double width) {
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  setSource(c);
  cairo_set_line_width(cr_, width);
  cairo_stroke(cr_);
}

void Canvas::fillRect(double x0, double y0, double x1, double y1, Rgb c, double alpha) {
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  cairo_set_source_rgba(cr_, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, alpha);
  cairo_fill(cr_);
}

void Canvas::marker(double x, double y, Marker m, double r, Rgb c) {
  // Areas roughly equal across shapes, so that no setting looks heavier than another.
  const double s = r * 0.89, t = r * 1.2;
  switch (m) {
    case Marker::Circle: cairo_arc(cr_, x, y, r, 0, 2 * std::numbers::pi); break;
    case Marker::Square: cairo_rectangle(cr_, x - s, y - s, 2 * s, 2 * s); break;
    case Marker::TriangleUp:
    case Marker::TriangleDown: {
      const double d = m == Marker::TriangleUp ? 1 : -1;
      cairo_move_to(cr_, x, y - d * t);
      cairo_line_to(cr_, x + t * 0.87, y + d * t * 0.5);
      cairo_line_to(cr_, x - t * 0.87, y + d * t * 0.5);
      cairo_close_path(cr_);
      break;
    }
    case Marker::Diamond:
      cairo_move_to(cr_, x, y - t);
      cairo_line_to(cr_, x + t * 0.8, y);
      cairo_line_to(cr_, x, y + t);
      cairo_line_to(cr_, x - t * 0.8, y);
      cairo_close_path(cr_);
      break;
    case Marker::Cross: {
      const double a = r, w = r * 0.35;   // a plus sign, arms of half-width w
      cairo_rectangle(cr_, x - a, y - w, 2 * a, 2 * w);
      cairo_rectangle(cr_, x - w, y - a, 2 * w, 2 * a);
      cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
      break;
    }
  }
  setSource(c);
  cairo_fill(cr_);
}

double Canvas::textWidth(const std::string& s, Font f) {
  useFont(f);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, s.c_str(), &e);
  return e.x_advance;
}

void Canvas::text(double x, double y, const std::string& s, Font f, Rgb c, Align a, double angle_deg) {
  const double w = textWidth(s, f);   // also selects the font
  cairo_font_extents_t fe;
  cairo_font_extents(cr_, &fe);
  const double dx = a == Align::Left ? 0 : a == Align::Centre ? -w / 2 : -w;
  const double dy = (fe.ascent - fe.descent) / 2;   // from the middle down to the baseline
  cairo_save(cr_);
  cairo_translate(cr_, x, y);
  cairo_rotate(cr_, angle_deg * std::numbers::pi / 180);
  cairo_move_to(cr_, dx, dy);
  setSource(c);
  cairo_show_text(cr_, s.c_str());
  cairo_restore(cr_);
  const double turn = angle_deg * std::numbers::pi / 180;
  labels_.push_back({s, x + dx * std::cos(turn) - dy * std::sin(turn), y + dx * std::sin(turn) + dy * std::cos(turn),
                     f.size, angle_deg, f.bold});
}

RgbImage Canvas::image() const {
  if (target_ != Target::Raster) throw std::logic_error("Canvas::image on a canvas that is not a raster");
  RgbImage img;
  unpackPixels(surface_, 3, img.width, img.height, img.pixels);
  return img;
}

RgbaImage Canvas::layer() const {
  if (target_ != Target::Layer) throw std::logic_error("Canvas::layer on a canvas that is not a layer");
  RgbaImage img;
  unpackPixels(surface_, 4, img.width, img.height, img.pixels);
  return img;
}

std::string Canvas::finishSvg(const std::string& title) {
  if (target_ != Target::Svg) throw std::logic_error("Canvas::finishSvg on a raster canvas");
  cairo_surface_finish(surface_);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(cairo_surface_status(surface_)));
  std::string layer = "<g id=\"text\" fill-opacity=\"0\" font-family=\"DejaVu Sans\">\n";
  for (const Label& l : labels_) {
    const std::string x = num(l.x), y = num(l.y);
    layer.append("<text x=\"").append(x).append("\" y=\"").append(y);
    layer.append("\" font-size=\"").append(num(l.size)).append("\"");
    if (l.bold) layer.append(" font-weight=\"bold\"");
    if (l.angle_deg != 0)
      layer.append(" transform=\"rotate(").append(num(l.angle_deg)).append(" ").append(x).append(" ").append(y).append(")\"");
    layer.append(">").append(xmlEscaped(l.s)).append("</text>\n");
  }
  layer += "</g>\n";
  std::string doc = renumberSurfaceIds(svg_);
  const std::size_t end = doc.rfind("</svg>");
  const std::size_t open = doc.find('>', doc.find("<svg"));
  if (end == std::string::npos || open == std::string::npos || open > end)
    throw std::runtime_error("cairo wrote no <svg> element");
  doc.insert(end, layer);
  doc.insert(open + 1, "\n<title>" + xmlEscaped(title) + "</title>");
  return doc;
}

}  // namespace tumble::plot
