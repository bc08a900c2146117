// The drawing surface of tumble's plots and of the text over frames, on cairo: antialiased lines,
// markers and text in DejaVu Sans (found through fontconfig, drawn through FreeType). One Canvas
// draws pixels, handed over as an RgbImage for src/io to write as PNG; or an SVG document, so the
// same drawing code makes both files; or a transparent RGBA layer to lay over a rendered frame
// (src/render/overlay_composite.h). The benchmark's plots and the energy plot both draw on it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/image.h"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace tumble::plot {

using Rgb = std::array<std::uint8_t, 3>;

enum class Marker { Circle, Square, TriangleUp, Diamond, TriangleDown, Cross };

struct Font {
  double size = 12;   // px
  bool bold = false;
};

enum class Align { Left, Centre, Right };

class Canvas {
 public:
  // Raster: an opaque white page; Svg: the same as a document; Layer: fully transparent pixels,
  // drawn over a frame (layer()).
  enum class Target { Raster, Svg, Layer };

  // A page of width x height px.
  Canvas(Target target, int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed = false);
  void polyline(const std::vector<std::pair<double, double>>& points, Rgb c, double width);
  void strokeRect(double x0, double y0, double x1, double y1, Rgb c, double width);
  // A filled rectangle, `alpha` (0..1) opaque.
  void fillRect(double x0, double y0, double x1, double y1, Rgb c, double alpha = 1);
  // A filled marker centred on (x, y) whose shape fits a circle of `radius` px.
  void marker(double x, double y, Marker m, double radius, Rgb c);
  // Text whose vertical middle sits at y, aligned on x; `angle_deg` turns it about (x, y)
  // (-90: reads upwards, as a y-axis title).
  void text(double x, double y, const std::string& s, Font f, Rgb c, Align a = Align::Left, double angle_deg = 0);
  double textWidth(const std::string& s, Font f);

  // Raster canvases: the pixels drawn so far.
  RgbImage image() const;
  // Layer canvases: the pixels drawn so far, RGBA with the colour premultiplied by alpha (cairo's
  // own form: laying it over a picture is out = layer + (1 - alpha) picture, per channel).
  RgbaImage layer() const;
  // Svg canvases: ends the drawing and returns the document, titled `title`. cairo draws text as
  // glyph outlines, which no search, screen reader or test can read; so every string drawn is
  // also laid over its outlines as invisible SVG <text>, from the same text() call that drew it.
  std::string finishSvg(const std::string& title);

 private:
  struct Label {
    std::string s;
    double x, y, size, angle_deg;   // baseline start, as drawn
    bool bold;
  };

  void setSource(Rgb c);
  void useFont(Font f);

  Target target_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
  std::string svg_;                 // the SVG surface's output, streamed as cairo writes it
  std::vector<Label> labels_;
};

}  // namespace tumble::plot
