// The documented exit codes, from the real executable.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

fs::path freshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("tumble_cli_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("tumble --help documents the subcommands and exit codes and exits 0", "[cli]") {
  auto r = runTumble("--help");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("render") && Catch::Contains("simulate") && Catch::Contains("check"));
  CHECK_THAT(r.output, Catch::Contains("65") && Catch::Contains("73"));
  auto sub = runTumble("render --help");
  CHECK(sub.exit_code == 0);
  CHECK_THAT(sub.output, Catch::Contains("--overwrite") && Catch::Contains("--crf") && Catch::Contains("--size"));
}

TEST_CASE("a bad command line exits 64", "[cli]") {
  CHECK(runTumble("").exit_code == 64);
  CHECK(runTumble("render").exit_code == 64);
  CHECK(runTumble("render " + kScene + " --no-such-flag").exit_code == 64);
  CHECK(runTumble("render " + kScene + " --size 12x").exit_code == 64);
  CHECK(runTumble("render " + kScene + " --frames 0..3").exit_code == 64);
  CHECK(runTumble("render " + kScene + " -o out.avi").exit_code == 64);
}

TEST_CASE("a missing scene exits 66 and names it", "[cli]") {
  auto r = runTumble("check /no/such/scene.json");
  CHECK(r.exit_code == 66);
  CHECK_THAT(r.output, Catch::Contains("/no/such/scene.json"));
}

TEST_CASE("a bad scene exits 65 with file, line and field", "[cli]") {
  fs::path dir = freshDir("bad_scene");
  std::ofstream(dir / "bad.json") << "{\"schema_version\": 1,\n \"bodies\": [{\"shape\": \"box\", \"frction\": 0.2}]}";
  auto r = runTumble("check " + (dir / "bad.json").string());
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("bad.json:2:") && Catch::Contains("/bodies/0/frction") &&
                           Catch::Contains("did you mean \"friction\""));
}

TEST_CASE("check validates and describes the scene", "[cli]") {
  auto r = runTumble("check " + kScene);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("valid") && Catch::Contains("box") && Catch::Contains("integrate"));
}

TEST_CASE("an existing output is refused (73) unless -y, before any work", "[cli]") {
  fs::path dir = freshDir("overwrite");
  fs::path out = dir / "clip.mp4";
  std::ofstream(out) << "precious";
  auto r = runTumble("render " + kScene + " -q -o " + out.string());
  CHECK(r.exit_code == 73);
  CHECK_THAT(r.output, Catch::Contains("clip.mp4") && Catch::Contains("--overwrite"));
  std::ifstream in(out);
  std::string content((std::istreambuf_iterator<char>(in)), {});
  CHECK(content == "precious");
  CHECK(runTumble("render " + kScene + " -q -y -o " + out.string()).exit_code == 0);
  CHECK(fs::file_size(out) > 1000);
}

TEST_CASE("an unwritable output exits 73", "[cli]") {
  fs::path dir = freshDir("unwritable");
  std::ofstream(dir / "file") << "x";   // a file where a folder is needed
  auto r = runTumble("render " + kScene + " -q -o " + (dir / "file" / "clip.mp4").string());
  CHECK(r.exit_code == 73);
}

TEST_CASE("simulate writes an exact, stable trajectory CSV", "[cli]") {
  fs::path dir = freshDir("simulate");
  auto r = runTumble("simulate " + kScene + " -q --trajectory " + (dir / "a.csv").string());
  REQUIRE(r.exit_code == 0);
  runTumble("simulate " + kScene + " -q --trajectory " + (dir / "b.csv").string());
  std::ifstream a(dir / "a.csv"), b(dir / "b.csv");
  std::string ta((std::istreambuf_iterator<char>(a)), {}), tb((std::istreambuf_iterator<char>(b)), {});
  CHECK(ta == tb);   // deterministic across processes
  // tumble's line naming the scene's motion, then the header
  CHECK(ta.rfind("# tumble trajectory; motion-hash=", 0) == 0);
  CHECK(ta.find("; rows=frame; scene=small_box.json\ntime,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n") != std::string::npos);
  // 10 frames x 2 bodies + header + tumble's line
  CHECK(std::count(ta.begin(), ta.end(), '\n') == 22);
  auto steps = runTumble("simulate " + kScene + " -q --every-step --trajectory " + (dir / "c.csv").string());
  REQUIRE(steps.exit_code == 0);
  std::ifstream c(dir / "c.csv");
  std::string tc((std::istreambuf_iterator<char>(c)), {});
  // 9 frame intervals x 24 steps (1/240 s nearest divisor of 1/10 s) + the initial state, x 2 bodies
  CHECK(std::count(tc.begin(), tc.end(), '\n') == 2 + 2 * (9 * 24 + 1));
  CHECK(tc.find("; rows=step;") != std::string::npos);
}

TEST_CASE("simulate reports an accuracy target, and a miss as a warning even with -q, still exiting 0", "[cli]") {
  fs::path dir = freshDir("target");
  auto scene = [&](const std::string& name, const std::string& simulation) {
    std::ofstream(dir / name) << R"({ "schema_version": 1, "render": { "fps": 10, "frames": 12 },
      "simulation": )" << simulation << R"(,
      "bodies": [ { "name": "ground", "shape": "plane" },
                  { "name": "cube", "shape": "box", "position_m": [0, 0, 1], "restitution": 0.5 } ] })";
    return (dir / name).string();
  };
  // The Baraff model lands the cube within its 1e-6 m tolerance: a 1e-9 m target is missed.
  auto missed = runTumble("simulate -q " + scene("missed.json", R"({ "contact_model": "baraff",
      "target": { "penetration_m": 1e-9 } })"));
  CHECK(missed.exit_code == 0);
  CHECK(missed.output.find("tumble: warning: accuracy target missed: deepest contact") != std::string::npos);
  CHECK(missed.output.find("\"cube\" and \"ground\"") != std::string::npos);
  auto met = runTumble("simulate " + scene("met.json", R"({ "target": { "penetration_m": 1e-3, "energy_drift": 1e-3 } })"));
  CHECK(met.exit_code == 0);
  CHECK(met.output.find("tumble: target: deepest contact") != std::string::npos);
  CHECK(met.output.find("tumble: target: largest energy rise") != std::string::npos);
  CHECK(met.output.find("missed") == std::string::npos);
}
