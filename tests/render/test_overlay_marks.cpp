// Overlay marks (render/marks_pass.h) drawn over a frame, and the text layer laid over a read-back
// image (render/overlay_composite.h).
#include <catch2/catch.hpp>

#include "box_frame.h"
#include "box_mesh.h"
#include "render_config.h"
#include "render/camera_matrices.h"
#include "render/marks_pass.h"
#include "render/overlay_composite.h"
#include "render/renderer.h"

using namespace tumble;

namespace {

constexpr int kWidth = 160, kHeight = 120;

RgbImage renderBox(const DrawMarks& marks) {
  auto renderer = Renderer::create(test::testConfig(kWidth, kHeight, 512));
  DrawFrame frame = test::boxFrame();
  frame.instances[0].mesh = renderer->addMesh(test::boxMesh({0.5f, 0.5f, 0.5f}));
  frame.marks = marks;
  renderer->draw(frame);
  RgbImage img;
  renderer->readBack(img);
  return img;
}

int countColour(const RgbImage& img, int r, int g, int b, int tolerance) {
  int n = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 3)
    n += std::abs(img.pixels[i] - r) <= tolerance && std::abs(img.pixels[i + 1] - g) <= tolerance &&
         std::abs(img.pixels[i + 2] - b) <= tolerance;
  return n;
}

}  // namespace

TEST_CASE("marks are drawn over the bodies, in their sRGB colour, with a dark outline", "[render][overlays]") {
  DrawMarks marks;
  marks.line_px = 2;
  marks.dot_px = 8;
  // A green segment through the middle of the box (inside it: the depth test is off), and a dot.
  marks.segments.push_back({{-0.4f, 0, 1}, {0.4f, 0, 1}, {0, 1, 0}});
  marks.dots.push_back({{0, 0, 2.5f}, {0, 0, 1}});
  const RgbImage plain = renderBox({});
  const RgbImage marked = renderBox(marks);
  CHECK(countColour(plain, 0, 255, 0, 10) == 0);
  CHECK(countColour(marked, 0, 255, 0, 10) > 20);    // ~ 2 px x the segment's ~30 px
  CHECK(countColour(marked, 0, 0, 255, 10) > 20);    // the dot: ~ pi 4^2 px
  CHECK(countColour(marked, 20, 20, 20, 12) > 20);   // its outline
  CHECK(renderBox(marks).pixels == marked.pixels);    // deterministic
}

TEST_CASE("faint lines blend over the frame at their alpha, without an outline", "[render][overlays]") {
  DrawMarks marks;
  marks.faint_px = 3;
  marks.faint.push_back({{-0.4f, 0, 1}, {0.4f, 0, 1}, {1, 0, 0}, 0.5f});   // red at half, through the box
  const RgbImage plain = renderBox({});
  const RgbImage faint = renderBox(marks);
  int halfway = 0, opaque = 0, outlined = 0;
  for (std::size_t i = 0; i < plain.pixels.size(); i += 3) {
    const int r0 = plain.pixels[i], r1 = faint.pixels[i];
    halfway += r1 != r0 && std::abs(r1 - (255 + r0) / 2) <= 3;
    opaque += r1 > (255 + r0) / 2 + 3;   // redder than half: drawn over, not blended
    outlined += faint.pixels[i] < 30 && faint.pixels[i + 1] < 30 && faint.pixels[i + 2] < 30 && r0 >= 30;
  }
  CHECK(halfway > 40);   // ~ 3 px x the segment's ~30 px
  CHECK(opaque == 0);
  CHECK(outlined == 0);
}

TEST_CASE("mark triangles: exact pixel widths, and nothing behind the camera", "[render][overlays]") {
  DrawCamera camera;
  camera.eye = {0, -5, 0};
  camera.target = {0, 0, 0};
  const Eigen::Matrix4f vp = render::cameraViewProjection(camera, float(kWidth) / kHeight);
  DrawMarks marks;
  marks.line_px = 4;
  marks.outline_px = 1;
  marks.segments.push_back({{-1, 0, 0}, {1, 0, 0}, {1, 1, 1}});
  std::vector<float> v;
  render::buildMarkTriangles(marks, vp, kWidth, kHeight, v);
  REQUIRE(v.size() == 2 * 6 * 6);   // outline quad, then the mark's: 6 vertices of x, y, r, g, b, a
  // The mark's quad spans 4 px vertically: 2 px either side of the centre row, in NDC 2/120 each.
  const float top = v[6 * 6 + 1], bottom = v[6 * 6 + 2 * 6 + 1];
  CHECK(std::abs(top - bottom) == Approx(4.0f * 2 / kHeight));
  marks.segments[0] = {{0, -6, 0}, {0, -7, 0}, {1, 1, 1}};   // behind the eye
  render::buildMarkTriangles(marks, vp, kWidth, kHeight, v);
  CHECK(v.empty());
}

TEST_CASE("a layer composites over a frame: transparent keeps, opaque replaces, half blends, outside is cut", "[render][overlays]") {
  RgbImage frame{2, 1, {100, 100, 100, 100, 100, 100}};
  RgbaImage layer{2, 1, {0, 0, 0, 0, 128, 0, 0, 128}};   // clear; red at alpha 0.5 (premultiplied)
  compositeOver(frame, layer);
  CHECK(frame.pixels == std::vector<std::uint8_t>{100, 100, 100, 178, 50, 50});
  // Placed at an offset, and cut at the frame's edge: only the pixel inside changes.
  RgbImage wide{3, 1, {0, 0, 0, 0, 0, 0, 0, 0, 0}};
  compositeOver(wide, RgbaImage{2, 1, {10, 20, 30, 255, 40, 50, 60, 255}}, 2, 0);
  CHECK(wide.pixels == std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 10, 20, 30});
  compositeOver(wide, RgbaImage{1, 1, {99, 99, 99, 255}}, -1, 0);   // wholly outside
  CHECK(wide.pixels[0] == 0);
}
