// A shadow's edge on the ground is anti-aliased: shading runs once per pixel, so MSAA does not
// smooth it, and the shadow filter must (shaders/lighting.glsl). A hard edge crosses each row of
// pixels in one jump, which shows as a serrated staircase along a slanted edge.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

#include "box_frame.h"
#include "box_mesh.h"
#include "render_config.h"
#include "render/camera_matrices.h"
#include "render/renderer.h"

using namespace tumble;

namespace {

constexpr int kWidth = 320, kHeight = 240;

// Image row of a world point on the ground.
int rowOf(const DrawFrame& frame, const Eigen::Vector3f& p) {
  const Eigen::Matrix4f vp = render::cameraViewProjection(frame.camera, float(kWidth) / kHeight);
  const Eigen::Vector4f c = vp * p.homogeneous();
  return static_cast<int>((0.5f - 0.5f * c.y() / c.w()) * kHeight);
}

int greyAt(const RgbImage& img, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
  return img.pixels[i] + img.pixels[i + 1] + img.pixels[i + 2];
}

}  // namespace

TEST_CASE("a shadow's edge on the ground passes through intermediate greys", "[render]") {
  // test::boxFrame's shadow has slanted edges. With a 2048 map the texels are far smaller than
  // a pixel at this size, so whatever smooths the edge is the filter, not the map's coarseness.
  const RenderConfig config = test::testConfig(kWidth, kHeight, 2048);
  auto renderer = Renderer::create(config);
  renderer->addMesh(test::boxMesh({0.5f, 0.5f, 0.5f}));
  const DrawFrame frame = test::boxFrame();
  renderer->draw(frame);
  RgbImage img;
  renderer->readBack(img);

  // Rows through the shadow (centred on the box centre's shadow at (1, 0.3, 0)); each crosses
  // lit ground, the shadow and lit ground again. The plain ground shades evenly along a row, so
  // the darkest and brightest pixels of the row are the shadow's and the lit ground's greys.
  const int centre_row = rowOf(frame, {1, 0.3f, 0});
  int crossings = 0, intermediate = 0;
  std::set<int> levels;
  for (int y = centre_row - 4; y <= centre_row + 4; ++y) {
    std::vector<int> row;
    for (int x = kWidth / 2; x < kWidth; ++x) row.push_back(greyAt(img, x, y));
    const auto [dark, bright] = std::minmax_element(row.begin(), row.end());
    REQUIRE(*bright - *dark > 60);  // the row does cross the shadow
    // Acceptance bound: a grey counts as intermediate 5% of the step away from either end, well
    // clear of the rounding of a flat colour (1 in 255 per channel).
    const int margin = (*bright - *dark) / 20;
    crossings += 2;
    for (int g : row) {
      if (g > *dark + margin && g < *bright - margin) {
        ++intermediate;
        levels.insert(g);
      }
    }
  }
  // Acceptance bounds: every crossing of an edge passes through at least one intermediate grey
  // (a hard edge jumps in one step: none), and across the rows the greys take several levels
  // (the filter's eight samples give up to seven between fully lit and fully shadowed).
  CHECK(intermediate >= crossings);
  CHECK(levels.size() >= 5);
}
