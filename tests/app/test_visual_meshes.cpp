// Mesh bodies drawn as their files hold them, through the real command line: a texture that cannot
// be decoded is a warning naming it (the render goes on), "draw": "hulls" shows the collision
// pieces instead, and a scene's colour replaces the file's materials.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kSource = TUMBLE_SOURCE_DIR;

fs::path freshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("tumble_visual_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A test scene with one piece of text replaced, written into `dir` with its mesh paths made
// absolute (they are relative to tests/scenes/).
std::string editedScene(const fs::path& dir, const std::string& scene, const std::string& from, const std::string& to) {
  std::ifstream in(kSource + "/tests/scenes/" + scene);
  std::string text{std::istreambuf_iterator<char>(in), {}};
  for (auto [a, b] : {std::pair{from, to}, std::pair{std::string("../assets/"), kSource + "/tests/assets/"}}) {
    const std::size_t at = text.find(a);
    REQUIRE(at != std::string::npos);
    text.replace(at, a.size(), b);
  }
  const fs::path path = dir / scene;
  std::ofstream(path) << text;
  return path.string();
}

struct Rgb {
  int r, g, b;
};

Rgb centre(const fs::path& png) {
  const tumble::RgbImage image = tumble::readPng(png);
  const std::size_t i = (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 3;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

}  // namespace

TEST_CASE("a texture that cannot be decoded is a warning naming it, and the frame is rendered", "[visual][cli]") {
  const fs::path dir = freshDir("bad_texture");
  auto r = runTumble("render " + kSource + "/tests/scenes/visual_bad_texture.json --frames 1 -y -o " +
                     (dir / "shot.png").string());
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("warning: body \"crate\": texture ") &&
                           Catch::Contains("not_an_image.png: not an image tumble can decode"));
  CHECK(fs::exists(dir / "shot.png"));
  // -q keeps it quiet, as every warning.
  auto quiet = runTumble("render " + kSource + "/tests/scenes/visual_bad_texture.json --frames 1 -q -y -o " +
                         (dir / "quiet.png").string());
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.output.empty());
}

TEST_CASE("a torus shows the ground through its hole, and its hull with draw hulls does not", "[visual][cli]") {
  const fs::path dir = freshDir("torus");
  const std::string scene = kSource + "/tests/scenes/visual_torus.json";
  REQUIRE(runTumble("render " + scene + " --frames 1 -q -y -o " + (dir / "visual.png").string()).exit_code == 0);
  const std::string hulls =
      editedScene(dir, "visual_torus.json", "\"color\": \"#3aa17e\"", "\"color\": \"#3aa17e\", \"draw\": \"hulls\"");
  auto r = runTumble("render " + hulls + " --frames 1 -q -y -o " + (dir / "hulls.png").string());
  REQUIRE(r.exit_code == 0);
  const Rgb hole = centre(dir / "visual.png"), hull = centre(dir / "hulls.png");
  CHECK(std::abs(hole.r - hole.g) < 10);   // the grey ground
  CHECK(hull.g > hull.r + 40);             // the green hull
}

TEST_CASE("a body's colour in the scene replaces its file's colours and textures", "[visual][cli]") {
  const fs::path dir = freshDir("colour");
  const std::string own = kSource + "/tests/scenes/visual_mtl_obj.json";
  const std::string red = editedScene(dir, "visual_mtl_obj.json", "\"rotation_deg\": [0, 0, 20]",
                                      "\"rotation_deg\": [0, 0, 20], \"color\": \"#ff0000\"");
  REQUIRE(runTumble("render " + own + " --frames 1 -q -y -o " + (dir / "own.png").string()).exit_code == 0);
  REQUIRE(runTumble("render " + red + " --frames 1 -q -y -o " + (dir / "red.png").string()).exit_code == 0);
  // Down the middle of the picture runs the box's striped side (its stripes across), then plain red.
  const tumble::RgbImage own_image = tumble::readPng(dir / "own.png"), red_image = tumble::readPng(dir / "red.png");
  int own_light = 0, red_light = 0;   // light stripe pixels: every channel high
  auto light = [](const tumble::RgbImage& image, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + 75) * 3;
    return image.pixels[i] > 150 && image.pixels[i + 1] > 150 && image.pixels[i + 2] > 150 ? 1 : 0;
  };
  for (int y = 45; y < 85; ++y) {
    own_light += light(own_image, y);
    red_light += light(red_image, y);
  }
  CHECK(own_light > 8);
  CHECK(red_light == 0);
  CHECK(centre(dir / "red.png").r > 2 * centre(dir / "red.png").g);
}
