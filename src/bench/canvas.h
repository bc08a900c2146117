// The drawing surface of the benchmark plots, on cairo: antialiased lines, markers and text in
// DejaVu Sans (found through fontconfig, drawn through FreeType). One Canvas draws either pixels,
// handed over as an RgbImage for src/io to write as PNG, or an SVG document, so the same drawing
// code makes both files.
#pragma once

#include <string>
#include <vector>

#include "base/image.h"
#include "bench/series_style.h"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace tumble::bench {

struct Font {
  double size = 12;   // px
  bool bold = false;
};

enum class Align { Left, Centre, Right };

class Canvas {
 public:
  enum class Target { Raster, Svg };

  // A white page of width x height px.
  Canvas(Target target, int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed = false);
  void polyline(const std::vector<std::pair<double, double>>& points, Rgb c, double width);
  void strokeRect(double x0, double y0, double x1, double y1, Rgb c, double width);
  // A filled marker centred on (x, y) whose shape fits a circle of `radius` px.
  void marker(double x, double y, Marker m, double radius, Rgb c);
  // Text whose vertical middle sits at y, aligned on x; `angle_deg` turns it about (x, y)
  // (-90: reads upwards, as a y-axis title).
  void text(double x, double y, const std::string& s, Font f, Rgb c, Align a = Align::Left, double angle_deg = 0);
  double textWidth(const std::string& s, Font f);

  // Raster canvases: the pixels drawn so far.
  RgbImage image() const;
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

}  // namespace tumble::bench
