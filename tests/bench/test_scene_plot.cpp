// A scene's plot on made-up results: written as PNG and SVG, named axes and series, the same bytes
// every time. No simulation runs here.
#include <catch2/catch.hpp>
#include <filesystem>

#include "bench/report.h"
#include "bench/series_style.h"
#include "bench_test_support.h"
#include "io/png_file.h"

using namespace tumble::bench;
namespace fs = std::filesystem;

namespace {

RunResult row(const std::string& setting, double dt, double wall, double apex_err) {
  return testing::madeUpRow("S1", setting, dt, wall, {{"apex_err", apex_err}});
}

SceneResults cubeDrop() {
  SceneResults s{makeScene("S1", {1.0 / 60, 1.0 / 240}), {}, {}};
  s.rows = {row("tumble-auto", 1.0 / 60, 1.8e-4, 1.8e-4), row("tumble-auto", 1.0 / 240, 4.4e-4, 0),
            row("tumble-rk4", 1.0 / 60, 1.2e-4, 1.8e-4), row("tumble-rk4", 1.0 / 240, 4.4e-4, 1.8e-5),
            row("tumble-ts", 1.0 / 60, 3e-5, 2.5e-2), row("tumble-ts", 1.0 / 240, 9e-5, 6e-3),
            row("bullet", 1.0 / 60, 8.9e-5, 0.17), row("bullet", 1.0 / 240, 3e-4, 0.12)};
  return s;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Characters (UTF-8 code points) in the SVG's <text> elements, entities counted as one.
std::size_t charactersInTextLayer(const std::string& svg) {
  std::size_t n = 0;
  for (std::size_t at = svg.find("<text "); at != std::string::npos; at = svg.find("<text ", at + 1)) {
    const std::size_t from = svg.find('>', at) + 1, to = svg.find("</text>", from);
    for (std::size_t i = from; i < to; ++i) {
      if (svg[i] == '&') i = svg.find(';', i);
      else if ((static_cast<unsigned char>(svg[i]) & 0xC0) == 0x80) continue;   // inside a code point
      ++n;
    }
  }
  return n;
}

std::size_t pixelsOf(const tumble::RgbImage& img, Rgb c) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 3)
    n += img.pixels[i] == c[0] && img.pixels[i + 1] == c[1] && img.pixels[i + 2] == c[2];
  return n;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(TUMBLE_BINARY_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("a plot is written as a PNG and, beside it, an SVG of the same size") {
  const fs::path dir = freshDir("plot-files");
  writePlot(dir / "S1.png", cubeDrop());
  const tumble::RgbImage png = tumble::readPng(dir / "S1.png");
  CHECK(png.width == 960);
  CHECK(png.height == 600);
  const std::string svg = testing::fileBytes(dir / "S1.svg");
  CHECK(svg.find("width=\"960px\" height=\"600px\"") != std::string::npos);
  // Each family's colour is drawn: the markers' insides are the series' colour exactly.
  CHECK(pixelsOf(png, seriesStyle(Family::TumbleAuto, 0).colour) > 50);
  CHECK(pixelsOf(png, seriesStyle(Family::TumbleBaraff, 0).colour) > 50);
  CHECK(pixelsOf(png, seriesStyle(Family::TumbleTimeStepping, 0).colour) > 50);
  CHECK(pixelsOf(png, seriesStyle(Family::Bullet, 0).colour) > 50);
}

// cairo's SVG surface draws text as glyph outlines (<use> of a <symbol> per glyph), which hold no
// characters. The Canvas lays every string it draws over its outlines as invisible <text> from the
// same call (canvas.h), so these checks fail when the plot stops drawing an axis title, a tick
// label or a series' name. That the same strings were drawn as outlines is checked by count:
// cairo's plain text API places one glyph per character, spaces included (no ligatures).
TEST_CASE("the SVG names its title, its axes with units, its decades and every series") {
  const fs::path dir = freshDir("plot-svg");
  writePlot(dir / "S1.png", cubeDrop());
  const std::string svg = testing::fileBytes(dir / "S1.svg");
  CHECK(svg.find("<title>S1 cube drop</title>") != std::string::npos);
  auto label = [&](const std::string& s) { return svg.find(">" + s + "</text>") != std::string::npos; };
  CHECK(label("S1 cube drop"));
  CHECK(label("wall time per simulated second (s/s)"));
  CHECK(label("apex_err = |apex − 0.75 m| (m)"));
  for (const char* series : {"tumble-auto", "tumble-rk4", "tumble-ts", "bullet"}) CHECK(label(series));
  CHECK(!label("ode-quick"));   // no row, no legend entry
  // x from 3e-5 to 4.4e-4 s/s, y from 1.8e-5 to 0.17 m, and one exact zero.
  for (const char* tick : {"10⁻⁵", "10⁻⁴", "10⁻³", "10⁻¹", "10⁰", "0"}) CHECK(label(tick));
  CHECK(!label("10⁻⁶"));
  CHECK(count(svg, "<use xlink:href=\"#glyph") == charactersInTextLayer(svg));
}

TEST_CASE("the same data give the same PNG and SVG bytes") {
  const fs::path dir = freshDir("plot-twice");
  writePlot(dir / "a.png", cubeDrop());
  writePlot(dir / "b.png", cubeDrop());
  CHECK(testing::fileBytes(dir / "a.png") == testing::fileBytes(dir / "b.png"));
  CHECK(testing::fileBytes(dir / "a.svg") == testing::fileBytes(dir / "b.svg"));
  SceneResults other = cubeDrop();
  other.rows[2].metrics[0].value = 2e-4;   // and other data another picture
  writePlot(dir / "c.png", other);
  CHECK(testing::fileBytes(dir / "a.png") != testing::fileBytes(dir / "c.png"));
}
