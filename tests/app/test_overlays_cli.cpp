// render --overlay and the scene's "overlays" through the real executable: names and their errors,
// what a render from a trajectory file can draw, the energy plot's two files, and that overlays
// change the picture without changing the motion.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::freshTempDir;
using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kSource = TUMBLE_SOURCE_DIR;
const std::string kCubeDrop = kSource + "/scenes/cube_drop.json";

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("render --overlay refuses an unknown name with did-you-mean, as a bad command line", "[overlays][cli]") {
  const fs::path dir = freshTempDir("tumble_overlay_names");
  auto r = runTumble("render " + kCubeDrop + " --frames 1 --size 160x120 -o " + (dir / "f/").string() +
                     " --overlay hud,contcts");
  CHECK(r.exit_code == 64);
  CHECK_THAT(r.output, Catch::Contains("--overlay: unknown overlay \"contcts\"; did you mean \"contacts\"?"));
  CHECK_FALSE(fs::exists(dir / "f"));   // refused before any work
  auto far = runTumble("render " + kCubeDrop + " --frames 1 -o " + (dir / "f/").string() + " --overlay sparkles");
  CHECK(far.exit_code == 64);
  CHECK_THAT(far.output, Catch::Contains("the overlays are contacts, forces, velocities, hud, energy_plot, back_step, "
                                         "broad_phase, energy_inset"));
  auto near = runTumble("render " + kCubeDrop + " --frames 1 -o " + (dir / "f/").string() + " --overlay backstep");
  CHECK(near.exit_code == 64);
  CHECK_THAT(near.output, Catch::Contains("unknown overlay \"backstep\"; did you mean \"back_step\"?"));
}

TEST_CASE("a scene's overlay names are checked where they stand in the file", "[overlays][cli]") {
  auto r = runTumble("check " + kSource + "/tests/scene/bad/overlay_unknown_name.json");
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("overlay_unknown_name.json:3:23: /overlays/1: unknown overlay \"contcts\""));
  auto set = runTumble("check " + kCubeDrop + " --set 'overlays=[\"hud\",\"forcse\"]'");
  CHECK(set.exit_code == 65);
  CHECK_THAT(set.output, Catch::Contains("did you mean \"forces\"?"));
  auto inset = runTumble("check " + kCubeDrop + " --set 'overlays=[\"hud\",\"energy_insert\"]'");
  CHECK(inset.exit_code == 65);
  CHECK_THAT(inset.output, Catch::Contains("/overlays/1: unknown overlay \"energy_insert\"; did you mean \"energy_inset\"?"));
}

TEST_CASE("check lists a scene's overlays", "[overlays][cli]") {
  auto r = runTumble("check " + kCubeDrop + " --set 'overlays=[\"hud\",\"velocities\"]' --set 'overlay_bodies=[\"cube\"]'");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("overlays  hud, velocities"));
  CHECK_THAT(r.output, Catch::Contains("velocities of cube"));
}

TEST_CASE("from a trajectory file only velocities can be drawn", "[overlays][cli]") {
  const fs::path dir = freshTempDir("tumble_overlay_trajectory");
  const std::string csv = (dir / "drop.csv").string();
  REQUIRE(runTumble("simulate " + kCubeDrop + " --duration 0.2 -q --trajectory " + csv).exit_code == 0);
  auto hud = runTumble("render " + kCubeDrop + " --from-trajectory " + csv + " --frames 1 --size 160x120 -o " +
                       (dir / "h/").string() + " --overlay hud");
  CHECK(hud.exit_code == 64);
  CHECK_THAT(hud.output, Catch::Contains("overlay hud needs the simulation's contacts and energy"));
  for (const char* kind : {"back_step", "broad_phase", "energy_inset"}) {
    INFO(kind);
    auto r = runTumble("render " + kCubeDrop + " --from-trajectory " + csv + " --frames 1 --size 160x120 -o " +
                       (dir / "k/").string() + " --overlay " + kind);
    CHECK(r.exit_code == 64);
    CHECK_THAT(r.output, Catch::Contains(std::string("overlay ") + kind + " needs the simulation's"));
  }
  auto vel = runTumble("render " + kCubeDrop + " --from-trajectory " + csv + " --frames 1,5 --size 160x120 -q -o " +
                       (dir / "v/").string() + " --overlay velocities");
  CHECK(vel.exit_code == 0);
  CHECK(fs::exists(dir / "v/frame_0005.png"));
}

TEST_CASE("the energy_plot overlay writes NAME.energy.png and .svg beside the output, and refuses to replace them", "[overlays][cli]") {
  const fs::path dir = freshTempDir("tumble_overlay_energy");
  const std::string video = (dir / "drop.mp4").string();
  auto r = runTumble("render " + kCubeDrop + " --duration 1 --size 160x120 -o " + video + " --overlay energy_plot");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("energy plot: " + (dir / "drop.energy.png").string()));
  const tumble::RgbImage png = tumble::readPng(dir / "drop.energy.png");
  CHECK(png.width == 960);
  const std::string svg = readFile(dir / "drop.energy.svg");
  for (const char* text : {">time (s)</text>", ">energy (J)</text>", ">kinetic</text>", ">potential (gravity)</text>",
                           ">total</text>", "cube_drop: energy (baraff)"})
    CHECK_THAT(svg, Catch::Contains(text));
  fs::remove(video);   // only the plot is left: it alone must stop the render
  auto again = runTumble("render " + kCubeDrop + " --duration 1 --size 160x120 -o " + video + " --overlay energy_plot");
  CHECK(again.exit_code == 73);
  CHECK_THAT(again.output, Catch::Contains("drop.energy.png already exists; add -y/--overwrite"));
  CHECK_FALSE(fs::exists(video));
}

TEST_CASE("overlays change the frames, not the motion, and are deterministic", "[overlays][cli]") {
  const fs::path dir = freshTempDir("tumble_overlay_frames");
  const std::string common = " --frames 14 --size 160x120 -q -o ";
  REQUIRE(runTumble("render " + kCubeDrop + common + (dir / "plain/").string()).exit_code == 0);
  const std::string marks = " --overlay contacts,forces --overlay velocities,hud"   // all but the plot's files
                            " --overlay back_step,broad_phase,energy_inset";
  REQUIRE(runTumble("render " + kCubeDrop + common + (dir / "a/").string() + marks).exit_code == 0);
  REQUIRE(runTumble("render " + kCubeDrop + common + (dir / "b/").string() + marks).exit_code == 0);
  CHECK(runTumble("diff -q --threshold 0 " + (dir / "a").string() + " " + (dir / "b").string()).exit_code == 0);
  CHECK(runTumble("diff -q --threshold 0 " + (dir / "plain").string() + " " + (dir / "a").string()).exit_code == 1);
  // The same trajectory with and without overlays in the scene: the motion hash leaves them out.
  const std::string a = (dir / "a.csv").string(), b = (dir / "b.csv").string();
  REQUIRE(runTumble("simulate " + kCubeDrop + " --duration 1 -q --trajectory " + a).exit_code == 0);
  REQUIRE(runTumble("simulate " + kCubeDrop + " --duration 1 -q --trajectory " + b +
                    " --set 'overlays=[\"contacts\",\"hud\"]'").exit_code == 0);
  CHECK(readFile(a) == readFile(b));
}

TEST_CASE("of a sharded render, the last chunk alone writes the energy plot", "[overlays][cli]") {
  const fs::path dir = freshTempDir("tumble_overlay_shards");
  const std::string render = "render " + kCubeDrop + " --duration 0.5 --size 160x120 -q -o " + (dir / "f/").string() +
                             " --overlay energy_plot --shard ";
  REQUIRE(runTumble(render + "1/2").exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "f/cube_drop.energy.png"));
  REQUIRE(runTumble(render + "2/2").exit_code == 0);
  CHECK(fs::exists(dir / "f/cube_drop.energy.svg"));
}
