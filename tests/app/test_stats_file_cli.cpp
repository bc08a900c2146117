// --stats FILE.json on render and simulate: the run's numbers as JSON, refused like any output.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

fs::path freshDir(const std::string& name) { return tumble::test::freshTempDir("tumble_stats_" + name); }

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

// A cube dropped on the ground: it lands, so there are contacts and a penetration to measure.
fs::path landingScene(const fs::path& dir) {
  std::ofstream(dir / "landing.json") << R"({ "schema_version": 1, "render": { "fps": 10, "frames": 12 },
    "bodies": [ { "name": "ground", "shape": "plane" },
                { "name": "cube", "shape": "box", "position_m": [0, 0, 1], "restitution": 0.5 } ] })";
  return dir / "landing.json";
}

}  // namespace

TEST_CASE("simulate --stats writes steps, stage times, contacts, energy drift and penetration", "[cli][stats]") {
  fs::path dir = freshDir("simulate");
  auto r = runTumble("simulate -q " + landingScene(dir).string() + " --stats " + (dir / "s.json").string());
  REQUIRE(r.exit_code == 0);
  nlohmann::json s = readJson(dir / "s.json");
  CHECK(s["command"] == "simulate");
  CHECK(s["frames"] == 12);
  CHECK(s["steps"] == 11 * 24);   // 1/240 s steps, 24 to each 1/10 s frame
  CHECK(s["simulated_s"].get<double>() == Approx(1.1));
  CHECK(s["stages_s"].contains("integrate"));
  CHECK(s["stages_s"]["integrate"].get<double>() > 0);
  CHECK(s["contacts"]["colliding"].get<long>() + s["contacts"]["resting"].get<long>() > 0);
  CHECK(s["steps_detail"].contains("back_steps"));
  // The landing cube sinks into the ground a little, by less than a millimetre.
  CHECK(s["deepest_penetration"]["m"].get<double>() > 0);
  CHECK(s["deepest_penetration"]["m"].get<double>() < 1e-3);
  CHECK(s["energy"]["drift"].get<double>() >= 0);
  CHECK(s["energy"]["end_j"].get<double>() < s["energy"]["start_j"].get<double>());   // the bounce loses energy
  CHECK(s["faults"] == 0);
}

TEST_CASE("render --stats adds the phases of rendering", "[cli][stats]") {
  fs::path dir = freshDir("render");
  auto r = runTumble("render -q " + kScene + " -o " + (dir / "f_####.png").string() + " --stats " +
                     (dir / "s.json").string());
  REQUIRE(r.exit_code == 0);
  nlohmann::json s = readJson(dir / "s.json");
  CHECK(s["command"] == "render");
  CHECK(s["frames_rendered"] == 10);
  for (const char* phase : {"simulate", "render", "read_back", "encode"}) CHECK(s["phases_s"].contains(phase));
  CHECK(s["phases_s"]["render"].get<double>() > 0);
}

TEST_CASE("render --stats tells the overlays' share of rendering", "[cli][stats]") {
  fs::path dir = freshDir("overlays");
  auto r = runTumble("render -q " + kScene + " --size 160x120 --overlay hud,contacts -o " +
                     (dir / "f_####.png").string() + " --stats " + (dir / "s.json").string());
  REQUIRE(r.exit_code == 0);
  nlohmann::json s = readJson(dir / "s.json");
  const double overlays = s["render_overlays_s"].get<double>(), render = s["phases_s"]["render"].get<double>();
  CHECK(overlays > 0);   // the HUD's text is drawn on every frame
  CHECK(overlays < render);
  CHECK(s["per_frame_median_ms"]["render_overlays"].get<double>() > 0);
}

TEST_CASE("an existing stats file is refused with 73 before any work, and replaced with -y", "[cli][stats]") {
  fs::path dir = freshDir("exists");
  std::ofstream(dir / "s.json") << "precious";
  auto r = runTumble("render -q " + kScene + " -o " + (dir / "f_####.png").string() + " --stats " +
                     (dir / "s.json").string());
  CHECK(r.exit_code == 73);
  CHECK_THAT(r.output, Catch::Contains("s.json") && Catch::Contains("--overwrite"));
  CHECK(!fs::exists(dir / "f_0001.png"));   // refused before any frame
  CHECK(runTumble("simulate -q " + kScene + " --stats " + (dir / "s.json").string()).exit_code == 73);
  std::ifstream in(dir / "s.json");
  CHECK(std::string((std::istreambuf_iterator<char>(in)), {}) == "precious");
  CHECK(runTumble("simulate -q -y " + kScene + " --stats " + (dir / "s.json").string()).exit_code == 0);
  CHECK(readJson(dir / "s.json")["command"] == "simulate");
}
