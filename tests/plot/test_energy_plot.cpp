// The energy plot names its axes and its series in the SVG (as text a reader or a test can find),
// draws its lines in the PNG, and the same data give the same bytes.
#include <catch2/catch.hpp>

#include <cmath>

#include "plot/canvas.h"
#include "plot/energy_plot.h"

using namespace tumble::plot;

namespace {

EnergySeries fallingBall() {
  EnergySeries s;
  s.title = "drop: energy (baraff)";
  for (int k = 0; k <= 60; ++k) {   // a 1 kg ball falling 2 m: kinetic rises as potential falls
    const double t = k / 60.0 * 0.6, h = 2 - 0.5 * 9.81 * t * t;
    s.time.push_back(t);
    s.potential.push_back(9.81 * h);
    s.kinetic.push_back(9.81 * (2 - h));
  }
  return s;
}

std::string svgOf(const EnergySeries& s) {
  Canvas c(Canvas::Target::Svg, kEnergyPlotWidth, kEnergyPlotHeight);
  drawEnergyPlot(c, s);
  return c.finishSvg(s.title);
}

}  // namespace

TEST_CASE("the energy plot's SVG names its title, axes and series", "[plot][overlays]") {
  const std::string svg = svgOf(fallingBall());
  for (const char* text : {"<title>drop: energy (baraff)</title>", ">time (s)</text>", ">energy (J)</text>",
                           ">kinetic</text>", ">potential (gravity)</text>", ">total</text>",
                           ">total = kinetic + potential</text>", ">0.6</text>", ">20</text>"})
    CHECK_THAT(svg, Catch::Contains(text));
  CHECK(svg == svgOf(fallingBall()));   // deterministic
}

TEST_CASE("the energy plot's PNG shows the total as a flat dark line across the plot", "[plot][overlays]") {
  Canvas c(Canvas::Target::Raster, kEnergyPlotWidth, kEnergyPlotHeight);
  drawEnergyPlot(c, fallingBall());
  const tumble::RgbImage img = c.image();
  REQUIRE(img.width == kEnergyPlotWidth);
  // The total is 19.62 J throughout: one row of dark pixels across the middle of the plot area.
  int dark_columns = 0;
  for (int x = 150; x < 650; x += 10) {
    bool dark = false;
    for (int y = 50; y < 470; ++y) {
      const std::uint8_t* p = &img.pixels[(static_cast<std::size_t>(y) * img.width + x) * 3];
      dark |= p[0] < 60 && p[1] < 60 && p[2] < 60;
    }
    dark_columns += dark;
  }
  CHECK(dark_columns == 50);
}

TEST_CASE("a layer canvas is transparent where nothing is drawn, premultiplied where it is", "[plot][overlays]") {
  Canvas c(Canvas::Target::Layer, 40, 20);
  c.fillRect(0, 0, 20, 20, {255, 0, 0}, 0.5);
  const tumble::RgbaImage layer = c.layer();
  const std::uint8_t* drawn = &layer.pixels[(10 * 40 + 5) * 4];
  const std::uint8_t* clear = &layer.pixels[(10 * 40 + 30) * 4];
  CHECK(int(drawn[3]) == Approx(128).margin(1));
  CHECK(int(drawn[0]) == Approx(128).margin(1));   // red 255 x alpha 0.5
  CHECK(int(drawn[1]) == 0);
  CHECK(int(clear[3]) == 0);
}
