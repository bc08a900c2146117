// The renderer end to end at 160x120: what lands where in the picture, shadows, orientation,
// determinism and the errors a user can hit.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "box_frame.h"
#include "box_mesh.h"
#include "render/camera_matrices.h"
#include "render/pixel_convert.h"
#include "render/renderer.h"

using namespace tumble;

namespace {

constexpr int kWidth = 160, kHeight = 120;

RenderConfig smallConfig() {
  RenderConfig config;
  config.width = kWidth;
  config.height = kHeight;
  config.shadow_map_size = 512;
  config.shader_dir = std::filesystem::path(TUMBLE_SOURCE_DIR) / "shaders";
  return config;
}

using test::boxFrame;

struct Pixel {
  int r, g, b;
  int sum() const { return r + g + b; }
};

Pixel at(const RgbImage& img, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
  return {img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]};
}

Pixel atWorld(const RgbImage& img, const DrawFrame& frame, const Eigen::Vector3f& p) {
  const Eigen::Matrix4f vp = render::cameraViewProjection(frame.camera, float(kWidth) / kHeight);
  const Eigen::Vector4f c = vp * p.homogeneous();
  const int x = static_cast<int>((c.x() / c.w() * 0.5f + 0.5f) * kWidth);
  const int y = static_cast<int>((0.5f - 0.5f * c.y() / c.w()) * kHeight);  // row 0 at the top
  REQUIRE(x >= 0);
  REQUIRE(x < kWidth);
  REQUIRE(y >= 0);
  REQUIRE(y < kHeight);
  return at(img, x, y);
}

Pixel backgroundPixel(const DrawFrame& frame) {
  auto enc = [](float v) { return static_cast<int>(render::encodeSrgb(v) * 255.0f + 0.5f); };
  return {enc(frame.background.x()), enc(frame.background.y()), enc(frame.background.z())};
}

bool near(Pixel a, Pixel b, int tolerance = 2) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance;
}

RgbImage renderOnce(const RenderConfig& config, const DrawFrame& frame) {
  auto renderer = Renderer::create(config);
  renderer->addMesh(test::boxMesh({0.5f, 0.5f, 0.5f}));
  renderer->draw(frame);
  RgbImage img;
  renderer->readBack(img);
  return img;
}

}  // namespace

TEST_CASE("a box above the ground lands where the camera says, with its shadow", "[render]") {
  const DrawFrame frame = boxFrame();
  const RgbImage img = renderOnce(smallConfig(), frame);
  REQUIRE(img.width == kWidth);
  REQUIRE(img.height == kHeight);
  REQUIRE(img.pixels.size() == std::size_t(kWidth * kHeight * 3));

  SECTION("the box's centre shows the box's hue") {
    const Pixel c = atWorld(img, frame, {0, 0, 1});
    CHECK(c.r > 2 * c.g);
    CHECK(c.r > 2 * c.b);
  }
  SECTION("the top is sky and the bottom is ground (not upside down)") {
    const Pixel sky = backgroundPixel(frame);
    CHECK(near(at(img, 0, 0), sky));
    CHECK(near(at(img, kWidth - 1, 0), sky));
    CHECK(near(at(img, kWidth / 2, 0), sky));
    for (int x : {0, kWidth / 2, kWidth - 1}) {
      const Pixel ground = at(img, x, kHeight - 1);
      CHECK_FALSE(near(ground, sky, 10));
      CHECK(std::abs(ground.r - ground.b) < 8);  // grey, not sky blue
    }
  }
  SECTION("the shadow on the ground is darker than lit ground on both sides") {
    // The box centre (0,0,1) projected along the light (1, 0.3, -1) onto z = 0.
    const Pixel shadow = atWorld(img, frame, {1, 0.3f, 0});
    const Pixel lit_left = atWorld(img, frame, {-1.5f, 0.3f, 0});
    const Pixel lit_right = atWorld(img, frame, {3.0f, 0.3f, 0});
    CHECK(shadow.sum() + 60 < lit_left.sum());
    CHECK(shadow.sum() + 60 < lit_right.sum());
  }
}

TEST_CASE("a body shadows the body below it", "[render]") {
  auto renderer = Renderer::create(smallConfig());
  renderer->addMesh(test::boxMesh({0.5f, 0.5f, 0.5f}));
  DrawFrame frame = boxFrame();
  frame.camera.eye = {0, -4, 5};
  frame.lights[0].direction = {0.05f, 0.05f, -1};  // nearly straight down
  frame.instances[0].model.translation() = Eigen::Vector3f(0, 0, 0.5f);
  RgbImage alone, covered;
  renderer->draw(frame);
  renderer->readBack(alone);
  DrawInstance above = frame.instances[0];
  above.model.translation() = Eigen::Vector3f(0, 0, 2.5f);
  above.colour = {0.05f, 0.05f, 0.8f};
  frame.instances.push_back(above);
  renderer->draw(frame);
  renderer->readBack(covered);
  // A point on the lower box's top face, seen below the upper box from this camera.
  const Eigen::Vector3f top_face(0, -0.4f, 1.0f);
  const Pixel lit = atWorld(alone, frame, top_face);
  const Pixel shaded = atWorld(covered, frame, top_face);
  CHECK(shaded.r > 2 * shaded.b);  // still the red box, not the blue one in front
  CHECK(shaded.sum() + 60 < lit.sum());
}

TEST_CASE("two draws of the same frame give identical bytes", "[render]") {
  auto renderer = Renderer::create(smallConfig());
  renderer->addMesh(test::boxMesh({0.5f, 0.5f, 0.5f}));
  DrawFrame frame = boxFrame();
  frame.ground.colour_b = {0.3f, 0.3f, 0.3f};  // with the checker, which uses derivatives
  RgbImage first, second;
  renderer->draw(frame);
  renderer->readBack(first);
  renderer->draw(frame);
  renderer->readBack(second);
  CHECK(first.pixels == second.pixels);
  // And a second renderer in the same process agrees too.
  CHECK(renderOnce(smallConfig(), frame).pixels == first.pixels);
}

TEST_CASE("without MSAA the frame still renders", "[render]") {
  RenderConfig config = smallConfig();
  config.samples = 1;
  const DrawFrame frame = boxFrame();
  const RgbImage img = renderOnce(config, frame);
  const Pixel c = atWorld(img, frame, {0, 0, 1});
  CHECK(c.r > 2 * c.g);
}

TEST_CASE("unsupported MSAA sample counts are refused clearly", "[render]") {
  RenderConfig config = smallConfig();
  config.samples = 8;
  try {
    Renderer::create(config);
    FAIL("samples = 8 was accepted");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("samples") && Catch::Contains("4"));
  }
}

TEST_CASE("a missing shader folder is MissingInput naming the file", "[render]") {
  RenderConfig config = smallConfig();
  config.shader_dir = "/nonexistent/tumble/shaders";
  try {
    Renderer::create(config);
    FAIL("a missing shader folder was accepted");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::MissingInput);
    CHECK_THAT(e.what(), Catch::Contains("/nonexistent/tumble/shaders/lit.vert"));
  }
}

TEST_CASE("a shader that does not compile is BadInput with the GLSL log", "[render]") {
  const auto source = std::filesystem::path(TUMBLE_SOURCE_DIR) / "shaders";
  const auto dir = std::filesystem::temp_directory_path() / "tumble_test_render_bad_shaders";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const auto& entry : std::filesystem::directory_iterator(source)) {
    std::filesystem::copy_file(entry.path(), dir / entry.path().filename());
  }
  std::ofstream(dir / "lit.frag", std::ios::app) << "\nthis is not glsl;\n";
  RenderConfig config = smallConfig();
  config.shader_dir = dir;
  try {
    Renderer::create(config);
    FAIL("a broken shader was accepted");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("lit.frag") && Catch::Contains("error"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("instances of unknown meshes are refused", "[render]") {
  auto renderer = Renderer::create(smallConfig());
  DrawFrame frame = boxFrame();  // refers to mesh 0, but none was added
  CHECK_THROWS_AS(renderer->draw(frame), Error);
}

namespace {

// The box as a mesh drawn as a file holds it: interpolated normals, and texture coordinates that
// spread the texture over the face towards the camera (-y), u along x and v up z.
DrawMesh texturedBox(int texture) {
  DrawMesh mesh = test::boxMesh({0.5f, 0.5f, 0.5f});
  mesh.shading = MeshShading::Surface;
  mesh.texture = texture;
  std::vector<Eigen::Vector3f> normals;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    normals.push_back(mesh.normals[i / 3]);
    mesh.uvs.emplace_back(mesh.positions[i].x() + 0.5f, mesh.positions[i].z() + 0.5f);
  }
  mesh.normals = normals;
  return mesh;
}

// 4x4 texels in quadrants, top row first: red | blue over green | yellow.
DrawTexture quadrantTexture() {
  DrawTexture t{4, 4, {}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const bool top = y < 2, left = x < 2;
      const std::uint8_t r = top == left || (!top && !left) ? 230 : 20;
      const std::uint8_t g = !top ? 200 : 20;
      const std::uint8_t b = top && !left ? 230 : 20;
      t.pixels.insert(t.pixels.end(), {r, g, b, 255});
    }
  return t;
}

}  // namespace

TEST_CASE("a mesh drawn as its file holds it shows its texture the right way up", "[render]") {
  DrawFrame frame = boxFrame();
  frame.instances[0].colour = {1, 1, 1};   // the texture's own colours
  auto renderer = Renderer::create(smallConfig());
  const int texture = renderer->addTexture(quadrantTexture());
  renderer->addMesh(texturedBox(texture));
  renderer->draw(frame);
  RgbImage img;
  renderer->readBack(img);
  const Pixel top_left = atWorld(img, frame, {-0.3f, -0.5f, 1.3f});
  const Pixel top_right = atWorld(img, frame, {0.3f, -0.5f, 1.3f});
  const Pixel bottom_left = atWorld(img, frame, {-0.3f, -0.5f, 0.7f});
  const Pixel bottom_right = atWorld(img, frame, {0.3f, -0.5f, 0.7f});
  CHECK((top_left.r > 2 * top_left.g && top_left.r > 2 * top_left.b));             // red
  CHECK((top_right.b > 2 * top_right.r && top_right.b > 2 * top_right.g));         // blue
  CHECK((bottom_left.g > 2 * bottom_left.r && bottom_left.g > 2 * bottom_left.b)); // green
  CHECK((bottom_right.r > 2 * bottom_right.b && bottom_right.g > 2 * bottom_right.b));   // yellow
}

TEST_CASE("a mesh without a texture is drawn in its instance's colour, and a missing texture is refused", "[render]") {
  const DrawFrame frame = boxFrame();   // a red box
  auto renderer = Renderer::create(smallConfig());
  renderer->addMesh(texturedBox(-1));
  renderer->draw(frame);
  RgbImage img;
  renderer->readBack(img);
  const Pixel c = atWorld(img, frame, {0, -0.5f, 1});
  CHECK(c.r > 2 * c.g);
  CHECK(c.r > 2 * c.b);
  try {
    renderer->addMesh(texturedBox(3));
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("texture 3"));
  }
}

TEST_CASE("faces lit past white keep their difference (tone mapping, not clipping)", "[render]") {
  DrawFrame frame = boxFrame();
  frame.camera.eye = {0, -4, 5};  // sees the top face and the front (-y) face
  frame.lights[0].intensity = 10.0f;
  frame.instances[0].colour = {0.8f, 0.8f, 0.8f};
  const RgbImage img = renderOnce(smallConfig(), frame);
  // Lambert terms 0.69 (top) and 0.21 (front) under this light: in linear light the faces reach
  // 5.5 and 1.7, both past white, which clamping would draw as the same flat 255.
  const Pixel top = atWorld(img, frame, {0.2f, -0.1f, 1.5f});
  const Pixel front = atWorld(img, frame, {0.2f, -0.5f, 0.8f});
  // Acceptance bounds: the brighter face stays the brighter by several levels per channel (the
  // curve gives about 14), and neither is pure white.
  CHECK(top.sum() >= front.sum() + 3 * 6);
  CHECK(top.sum() < 3 * 255);
  CHECK(front.sum() < 3 * 255);
}
