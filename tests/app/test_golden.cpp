// Visual regression, end to end through the real executable: renders are bit-identical across
// processes, match the golden frames in tests/golden/ (re-made by tools/update-golden), and the
// comparison catches a moved body, a colour change, a lost shadow, a flipped frame and a wrong size.
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
const std::string kScene = kSource + "/tests/scenes/small_box.json";
// The same frames tools/update-golden renders.
const std::string kRender = " --size 160x120 --samples 4 --frames 1,5,10 -q -y -o ";
// The golden tolerance. Measured on small_box at 160x120 (re-renders here differ by nothing):
//   body moved by one pixel (3.5 cm)  max diff 109..231, 0.88..1.24 % of pixels over 8
//   box red +16 of 255                max diff 12..16,   4.3..5.4 %
//   shadow off                        max diff 75,       1.3..1.6 %
// Threshold 8 lets every pixel drift by 3 % of full scale (another Mesa build's shading and
// rounding) and max-fail 0.5 % lets ~100 pixels differ freely (edges rasterised differently),
// yet each change above fails with margin. A colour change of 8 levels or less passes.
const std::string kTolerance = " --threshold 8 --max-fail 0.005";

fs::path freshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("tumble_golden_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// small_box.json with one piece of text replaced, written to `dir`.
std::string editedScene(const fs::path& dir, const std::string& from, const std::string& to) {
  std::string text = readFile(kScene);
  std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  fs::path path = dir / "scene.json";
  std::ofstream(path) << text;
  return path.string();
}

// Renders `scene`'s golden frames into dir/frames/ and diffs them against the golden ones.
tumble::test::RunResult renderAndDiff(const fs::path& dir, const std::string& scene) {
  REQUIRE(runTumble("render " + scene + kRender + (dir / "frames/").string()).exit_code == 0);
  return runTumble("diff " + kSource + "/tests/golden/small_box " + (dir / "frames").string() + kTolerance);
}

}  // namespace

TEST_CASE("renders match the golden frames at the golden tolerance", "[golden]") {
  fs::path dir = freshDir("match");
  auto small = runTumble("render " + kScene + kRender + (dir / "small/").string() + " --check-against " + kSource +
                         "/tests/golden/small_box" + kTolerance);
  CHECK(small.exit_code == 0);
  auto cube = runTumble("render " + kSource + "/scenes/cube_drop.json --size 160x120 --samples 4 --frames 1,14,30 -y -o " +
                        (dir / "cube/").string() + " --check-against " + kSource + "/tests/golden/cube_drop" + kTolerance);
  CHECK(cube.exit_code == 0);
  CHECK_THAT(cube.output, Catch::Contains("3 frames compared, 0 failed"));
}

TEST_CASE("meshes drawn as their files hold them match their golden frames", "[golden][visual]") {
  // A textured glTF, an OBJ coloured by its MTL (Kd and a map_Kd file) and a torus whose hole
  // shows the ground: the same scenes and frames tools/update-golden renders.
  fs::path dir = freshDir("visual");
  for (const char* name : {"visual_textured_gltf", "visual_mtl_obj", "visual_torus"}) {
    auto r = runTumble("render " + kSource + "/tests/scenes/" + name + ".json --size 160x120 --samples 4 --frames 1,5 -y -o " +
                       (dir / name).string() + "/ --check-against " + kSource + "/tests/golden/" + name + kTolerance);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("2 frames compared, 0 failed"));
  }
}

TEST_CASE("a follow and an orbit camera match their golden frames", "[golden][camera]") {
  fs::path dir = freshDir("cameras");
  for (const char* name : {"follow", "orbit"}) {
    auto r = runTumble("render " + kSource + "/tests/scenes/cameras.json --camera " + name +
                       " --size 160x120 --samples 4 --frames 1,5,10 -y -o " + (dir / name).string() + "/ --check-against " +
                       kSource + "/tests/golden/camera_" + name + kTolerance);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("3 frames compared, 0 failed"));
  }
}

TEST_CASE("a follow camera's frame is the same whichever frames are rendered", "[golden][camera]") {
  // Its lag depends on every frame before: each frame's camera comes from the whole motion.
  fs::path dir = freshDir("follow_alone");
  const std::string scene = kSource + "/tests/scenes/cameras.json --camera follow" + kRender.substr(0, kRender.find(" --frames"));
  REQUIRE(runTumble("render " + scene + " --frames 1..10 -q -y -o " + (dir / "all/").string()).exit_code == 0);
  REQUIRE(runTumble("render " + scene + " --frames 10 -q -y -o " + (dir / "alone/").string()).exit_code == 0);
  CHECK(readFile(dir / "all" / "frame_0010.png") == readFile(dir / "alone" / "frame_0010.png"));
  CHECK(readFile(dir / "all" / "frame_0010.png") != readFile(dir / "all" / "frame_0009.png"));
}

TEST_CASE("the same frame rendered by two processes is bit-identical", "[golden]") {
  fs::path dir = freshDir("twice");
  REQUIRE(runTumble("render " + kScene + kRender + (dir / "a/").string()).exit_code == 0);
  REQUIRE(runTumble("render " + kScene + kRender + (dir / "b/").string()).exit_code == 0);
  for (const char* name : {"frame_0001.png", "frame_0005.png", "frame_0010.png"}) {
    std::string a = readFile(dir / "a" / name);
    CHECK(a.size() > 1000);
    CHECK(a == readFile(dir / "b" / name));
  }
  auto r = runTumble("diff " + (dir / "a").string() + " " + (dir / "b").string() + " --threshold 0");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("PSNR inf"));
}

TEST_CASE("the golden comparison catches a body moved by one pixel", "[golden]") {
  fs::path dir = freshDir("moved");
  std::string scene = editedScene(dir, "[0, 0, 1.6]", "[0.035, 0, 1.6]");
  auto r = renderAndDiff(dir, scene);
  CHECK(r.exit_code == 1);
  CHECK(fs::file_size(dir / "frames" / "frame_0005.diff.png") > 100);   // a picture of what changed
  // The same in one go, rendering to a video: the diff images go beside it.
  auto check = runTumble("render " + scene + " --size 160x120 --samples 4 --frames 1,5,10 -y -o " +
                         (dir / "clip.mp4").string() + " --check-against " + kSource + "/tests/golden/small_box" +
                         kTolerance);
  CHECK(check.exit_code == 1);
  CHECK_THAT(check.output, Catch::Contains("3 frames compared, 3 failed"));
  CHECK(fs::exists(dir / "frame_0010.diff.png"));
}

TEST_CASE("the golden comparison catches a colour change", "[golden]") {
  fs::path dir = freshDir("colour");
  CHECK(renderAndDiff(dir, editedScene(dir, "#e04010", "#f04010")).exit_code == 1);
}

TEST_CASE("the golden comparison catches a missing shadow", "[golden]") {
  // The default lights with shadows off (the defaults cast shadows).
  fs::path dir = freshDir("shadow");
  std::string lights = R"("lights": [{ "type": "directional", "direction": [-0.4, 0.3, -1], "shadows": SHADOWS },
               { "type": "ambient", "color": "#c8d4e6", "intensity": 0.35 }], "bodies")";
  fs::path on = dir / "on", off = dir / "off";
  fs::create_directories(on);
  fs::create_directories(off);
  std::string with = editedScene(on, "\"bodies\"", std::string(lights).replace(lights.find("SHADOWS"), 7, "true"));
  std::string without = editedScene(off, "\"bodies\"", std::string(lights).replace(lights.find("SHADOWS"), 7, "false"));
  REQUIRE(runTumble("render " + with + kRender + (on / "frames/").string()).exit_code == 0);
  REQUIRE(runTumble("render " + without + kRender + (off / "frames/").string()).exit_code == 0);
  auto r = runTumble("diff " + (on / "frames").string() + " " + (off / "frames").string() + kTolerance);
  CHECK(r.exit_code == 1);
}

TEST_CASE("the golden comparison catches an upside-down frame", "[golden]") {
  fs::path dir = freshDir("flipped");
  fs::path golden = kSource + "/tests/golden/small_box/frame_0005.png";
  tumble::RgbImage image = tumble::readPng(golden), flipped = image;
  std::size_t row = 3 * static_cast<std::size_t>(image.width);
  for (int y = 0; y < image.height; ++y)
    std::copy_n(&image.pixels[y * row], row, &flipped.pixels[(image.height - 1 - y) * row]);
  tumble::writePng(dir / "flipped.png", flipped);
  auto r = runTumble("diff " + golden.string() + " " + (dir / "flipped.png").string() + kTolerance +
                     " --diff-out " + (dir / "diffs").string());
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("FAIL"));
  CHECK(fs::exists(dir / "diffs" / "flipped.diff.png"));
}

TEST_CASE("diff documents its own exit codes", "[golden][cli]") {
  auto r = runTumble("diff --help");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("--threshold") && Catch::Contains("--max-fail") &&
                           Catch::Contains("2   bad input") && Catch::Contains("64"));
  CHECK_THAT(runTumble("--help").output, Catch::Contains("diff"));
}

TEST_CASE("diff answers 2 for a different size or a missing frame, and says so", "[golden]") {
  fs::path dir = freshDir("bad");
  REQUIRE(runTumble("render " + kScene + " --size 160x128 --samples 4 --frames 1,5,10 -q -y -o " +
                    (dir / "frame_####.png").string()).exit_code == 0);
  std::string golden = kSource + "/tests/golden/small_box";
  auto size = runTumble("diff '" + golden + "/frame_%04d.png' '" + (dir / "frame_####.png").string() + "'" + kTolerance);
  CHECK(size.exit_code == 2);
  CHECK_THAT(size.output, Catch::Contains("sizes differ: 160x120 vs 160x128"));
  fs::remove(dir / "frame_0010.png");
  auto missing = runTumble("diff " + golden + " " + dir.string() + kTolerance);
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.output, Catch::Contains("frame_0010.png: missing in " + dir.string()));
  CHECK(runTumble("diff " + golden + "/frame_0001.png /no/such.png").exit_code == 2);
  CHECK(runTumble("diff " + golden + " " + golden + "/frame_0001.png").exit_code == 2);
  CHECK(runTumble("diff " + golden + " " + golden + " --threshold 300").exit_code == 64);
  auto no_golden = runTumble("render " + kScene + kRender + (dir / "out/").string() + " --check-against /no/such/dir");
  CHECK(no_golden.exit_code == 2);
  CHECK_THAT(no_golden.output, Catch::Contains("/no/such/dir is not a folder"));
}
