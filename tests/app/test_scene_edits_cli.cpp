// --set and --patch on the command line: applied before the scene is read, refused with the
// edit's name and the documented exit codes, and nothing written when refused.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

fs::path freshDir(const std::string& name) { return tumble::test::freshTempDir("tumble_edits_" + name); }

}  // namespace

TEST_CASE("render, simulate and check take --set and --patch", "[cli][edits]") {
  for (const char* command : {"render", "simulate", "check"}) {
    auto help = runTumble(std::string(command) + " --help");
    CHECK_THAT(help.output, Catch::Contains("--set") && Catch::Contains("--patch"));
  }
  auto r = runTumble("check " + kScene + " --set render.fps=20 --set bodies.box.mass_kg=3");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("20 fps") && Catch::Contains(" 3 "));
}

TEST_CASE("a --set changes the simulated motion", "[cli][edits]") {
  fs::path dir = freshDir("motion");
  REQUIRE(runTumble("simulate -q " + kScene + " --set 'bodies.box.velocity_m_s=[0,0,0]' --set "
                    "bodies.box.angular_velocity_rad_s=[0,0,0] --trajectory " + (dir / "t.csv").string())
              .exit_code == 0);
  std::ifstream in(dir / "t.csv");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  // Thrown up at 4 m/s in the file, the box now only falls: its velocity is never positive.
  CHECK(text.find("0,box,0,0,1.6,") != std::string::npos);
  CHECK(text.find(",0,0,4,") == std::string::npos);
}

TEST_CASE("a refused --set names the override and exits 65, a malformed one exits 64, and nothing is written", "[cli][edits]") {
  fs::path dir = freshDir("refused");
  const std::string out = " -o " + (dir / "clip.mp4").string();
  auto typo = runTumble("render -q " + kScene + out + " --set bodies.box.restitusion=0.9");
  CHECK(typo.exit_code == 65);
  CHECK_THAT(typo.output, Catch::Contains("--set bodies.box.restitusion: unknown field \"restitusion\"; "
                                          "did you mean \"restitution\"?"));
  CHECK_THAT(typo.output, !Catch::Contains("small_box.json:"));   // no line of the file holds it
  auto type = runTumble("render -q " + kScene + out + " --set bodies.box.restitution=high");
  CHECK(type.exit_code == 65);
  CHECK_THAT(type.output, Catch::Contains("--set bodies.box.restitution: expected a number"));
  auto malformed = runTumble("render -q " + kScene + out + " --set bodies.box.restitution");
  CHECK(malformed.exit_code == 64);
  CHECK_THAT(malformed.output, Catch::Contains("PATH=VALUE"));
  CHECK(fs::is_empty(dir));
}

TEST_CASE("a patch that is not JSON exits 65 located in it, a missing one 66, and nothing is written", "[cli][edits]") {
  fs::path dir = freshDir("patch");
  std::ofstream(dir / "broken.json") << "{\n  \"render\": {\"fps\": }\n}";
  std::ofstream(dir / "fix.json") << "{\n  \"bodies\": {\"box\": {\"mass_kg\": -2}}\n}";
  fs::path out_dir = dir / "out";
  const std::string out = " -o " + (out_dir / "frame_####.png").string();
  auto broken = runTumble("render -q " + kScene + out + " --patch " + (dir / "broken.json").string());
  CHECK(broken.exit_code == 65);
  CHECK_THAT(broken.output, Catch::Contains("broken.json:2:") && Catch::Contains("invalid JSON"));
  auto refused = runTumble("simulate -q " + kScene + " --patch " + (dir / "fix.json").string());
  CHECK(refused.exit_code == 65);
  CHECK_THAT(refused.output, Catch::Contains("fix.json:2:") && Catch::Contains("/bodies/box/mass_kg"));
  auto missing = runTumble("check " + kScene + " --patch " + (dir / "none.json").string());
  CHECK(missing.exit_code == 66);
  CHECK_THAT(missing.output, Catch::Contains("none.json: no such patch file"));
  CHECK(!fs::exists(out_dir));
}

TEST_CASE("a patch applies before --set, which wins", "[cli][edits]") {
  fs::path dir = freshDir("order");
  std::ofstream(dir / "p.json") << R"({"render": {"fps": 20}})";
  auto r = runTumble("check " + kScene + " --set render.fps=25 --patch " + (dir / "p.json").string());
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("25 fps"));
}
