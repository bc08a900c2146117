// render --from-trajectory, through the real executable: the same frames as a render that
// simulates, bit for bit, and a clear refusal of a trajectory that does not fit the scene.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "run_tumble.h"
#include "scale_out_files.h"

using namespace tumble::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene = kKnockdown;
const std::string kSmall = kSmallFrames + " -q";

std::string sceneCopy(const fs::path& dir, const std::string& name, const std::string& from, const std::string& to) {
  std::string text = fileBytes(kScene);
  std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

}  // namespace

TEST_CASE("frames rendered from a trajectory are bit-identical to frames of a render that simulates", "[scale-out]") {
  fs::path dir = freshFolder("from_trajectory");
  std::string csv = (dir / "motion.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --trajectory " + csv).exit_code == 0);
  CHECK(fileBytes(csv).rfind("# tumble trajectory; motion-hash=", 0) == 0);
  const std::string frames = " --frames 1,23,40,90,120";
  auto direct = runTumble("render " + kScene + kSmall + frames + " -o '" + (dir / "a" / "f_####.png").string() + "'");
  REQUIRE(direct.exit_code == 0);
  const std::string stats = (dir / "stats.json").string();
  auto read = runTumble("render " + kScene + kSmall + frames + " --from-trajectory " + csv + " --stats " + stats +
                        " -o '" + (dir / "b" / "f_####.png").string() + "'");
  INFO(read.output);
  REQUIRE(read.exit_code == 0);
  // Nothing was simulated: the stats say where the motion came from instead of stage times.
  CHECK_THAT(fileBytes(stats), Catch::Contains("\"motion_from_trajectory\"") && Catch::Contains("motion.csv"));
  for (int k : {1, 23, 40, 90, 120}) {
    INFO("frame " << k);
    std::string a = fileBytes(dir / "a" / frameName(k));
    REQUIRE(a.size() > 1000);
    CHECK(a == fileBytes(dir / "b" / frameName(k)));
  }
}

TEST_CASE("a trajectory from another scene is refused with exit 65, naming the file", "[scale-out]") {
  fs::path dir = freshFolder("other_scene");
  std::string csv = (dir / "motion.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --trajectory " + csv).exit_code == 0);
  std::string other = sceneCopy(dir, "slippery.json", "\"friction\": 0.6", "\"friction\": 0.2");
  auto r = runTumble("render " + other + kSmall + " --frames 5 --from-trajectory " + csv + " -o " + (dir / "x.png").string());
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("motion.csv") && Catch::Contains("another scene") &&
                           Catch::Contains("tumble simulate"));
  CHECK_FALSE(fs::exists(dir / "x.png"));
  // Timing flags change the motion too.
  CHECK(runTumble("render " + kScene + kSmall + " --fps 60 --frames 5 --from-trajectory " + csv + " -o " +
                  (dir / "y.png").string()).exit_code == 65);
  // So do --set and --patch: the same scene with a changed friction is another motion.
  CHECK(runTumble("render " + kScene + kSmall + " --set bodies.ground.friction=0.2 --frames 5 --from-trajectory " + csv +
                  " -o " + (dir / "w.png").string()).exit_code == 65);
  // What only changes the picture (the camera, a colour) keeps the motion: accepted.
  std::string moved = sceneCopy(dir, "moved.json", "\"fov_y_deg\": 45", "\"fov_y_deg\": 30");
  CHECK(runTumble("render " + moved + kSmall + " --frames 5 --from-trajectory " + csv + " -o " +
                  (dir / "z.png").string()).exit_code == 0);
}

TEST_CASE("a trajectory lacking a frame asked for, or not tumble's, is refused with exit 65", "[scale-out]") {
  fs::path dir = freshFolder("short");
  std::string csv = (dir / "short.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --duration 1 --trajectory " + csv).exit_code == 0);
  auto r = runTumble("render " + kScene + kSmall + " --frames 40 --from-trajectory " + csv + " -o " + (dir / "x.png").string());
  CHECK(r.exit_code == 65);
  CHECK_THAT(r.output, Catch::Contains("short.csv") && Catch::Contains("frames 1..31") && Catch::Contains("frame 40"));
  CHECK(runTumble("render " + kScene + kSmall + " --frames 31 --from-trajectory " + csv + " -o " +
                  (dir / "y.png").string()).exit_code == 0);

  std::string steps = (dir / "steps.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --duration 0.2 --every-step --trajectory " + steps).exit_code == 0);
  auto s = runTumble("render " + kScene + kSmall + " --frames 2 --from-trajectory " + steps + " -o " + (dir / "s.png").string());
  CHECK(s.exit_code == 65);
  CHECK_THAT(s.output, Catch::Contains("steps.csv") && Catch::Contains("--every-step"));

  std::string text = fileBytes(csv);
  std::ofstream(dir / "bare.csv") << text.substr(text.find('\n') + 1);   // without tumble's line
  auto b = runTumble("render " + kScene + kSmall + " --frames 2 --from-trajectory " + (dir / "bare.csv").string() +
                     " -o " + (dir / "b.png").string());
  CHECK(b.exit_code == 65);
  CHECK_THAT(b.output, Catch::Contains("bare.csv") && Catch::Contains("motion-hash"));
}

TEST_CASE("a missing trajectory exits 66 and names it", "[scale-out]") {
  fs::path dir = freshFolder("missing");
  auto r = runTumble("render " + kScene + kSmall + " --frames 2 --from-trajectory " + (dir / "nope.csv").string() +
                     " -o " + (dir / "x.png").string());
  CHECK(r.exit_code == 66);
  CHECK_THAT(r.output, Catch::Contains("nope.csv"));
}

TEST_CASE("moving cameras see the same frames from a trajectory: a fit camera holds the whole clip, a follow camera its lag", "[scale-out]") {
  fs::path dir = freshFolder("cameras");
  // The knock-down with two more cameras; the motion hash leaves cameras out.
  std::string scene = sceneCopy(dir, "cameras.json", "\"lights\":",
                                R"("cameras": [ { "name": "wide", "fit": "all", "yaw_deg": 10, "pitch_deg": 20 },
                                                { "name": "chase", "follow": { "body": "block_0", "offset_m": [0, -5, 2],
                                                                              "smoothing_s": 0.3 } } ],
                                   "lights":)");
  std::string csv = (dir / "motion.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --trajectory " + csv).exit_code == 0);
  for (const std::string camera : {"wide", "chase"}) {
    INFO(camera);
    const std::string common = "render " + scene + kSmall + " --camera " + camera + " --frames 12 -o ";
    REQUIRE(runTumble(common + (dir / (camera + "_a.png")).string()).exit_code == 0);
    auto r = runTumble(common + (dir / (camera + "_b.png")).string() + " --from-trajectory " + csv);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    std::string a = fileBytes(dir / (camera + "_a.png"));
    REQUIRE(a.size() > 1000);
    CHECK(a == fileBytes(dir / (camera + "_b.png")));
  }
}
