// Rendering in chunks through the real executable: --shard and the schedulers' variables pick
// contiguous chunks whose frames equal a single render's; video chunks join without re-encoding.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "../io/decode_video.h"
#include "run_tumble.h"
#include "scale_out_files.h"

using namespace tumble::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene = kKnockdown;
const std::string kFlags = " --duration 1" + kSmallFrames;
constexpr int kFrames = 31;   // 1 s at 30 frames/s: t = 0, 1/30 s, ..., 1 s

// Sets environment variables for the processes this test starts, and removes them after.
class ScopedEnv {
 public:
  explicit ScopedEnv(std::initializer_list<std::pair<std::string, std::string>> vars) : vars_(vars) {
    for (const auto& [name, value] : vars_) setenv(name.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() {
    for (const auto& [name, value] : vars_) unsetenv(name.c_str());
  }

 private:
  std::vector<std::pair<std::string, std::string>> vars_;
};

std::string simulateOnce(const fs::path& dir) {
  std::string csv = (dir / "motion.csv").string();
  REQUIRE(runTumble("simulate " + kScene + " -q --duration 1 --trajectory " + csv).exit_code == 0);
  return csv;
}

// Chunk i of 4 of the video dir/clip.mp4, from the trajectory `csv`.
void renderVideoChunk(const fs::path& dir, const std::string& csv, int i) {
  REQUIRE(runTumble("render " + kScene + kFlags + " -q --from-trajectory " + csv + " --shard " + std::to_string(i) +
                    "/4 -o " + (dir / "clip.mp4").string()).exit_code == 0);
}

std::string part(const fs::path& dir, int i) {
  char name[64];
  std::snprintf(name, sizeof name, "clip.part-%04d-of-0004.mp4", i);
  return (dir / name).string();
}

}  // namespace

TEST_CASE("four chunks from one trajectory give every frame once, each bit-identical to a single render", "[scale-out]") {
  fs::path dir = freshFolder("chunks");
  std::string csv = simulateOnce(dir);
  REQUIRE(runTumble("render " + kScene + kFlags + " -q -o '" + (dir / "whole" / "f_####.png").string() + "'").exit_code == 0);
  const std::string chunk_out = " -o '" + (dir / "chunks" / "f_####.png").string() + "'";
  // One chunk by flag, one as a Slurm array task, one as a Kubernetes Indexed Job pod, one by flag.
  auto first = runTumble("render " + kScene + kFlags + " --from-trajectory " + csv + " --shard 1/4" + chunk_out);
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  CHECK_THAT(first.output, Catch::Contains("chunk 1 of 4 (--shard 1/4): frames 1..7"));
  {
    ScopedEnv slurm({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "4"}});
    auto r = runTumble("render " + kScene + kFlags + " --from-trajectory " + csv + chunk_out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("chunk 2 of 4 (SLURM_ARRAY_TASK_ID=2 (array 1-4)): frames 8..15"));
  }
  {
    ScopedEnv k8s({{"JOB_COMPLETION_INDEX", "2"}});
    auto r = runTumble("render " + kScene + kFlags + " --from-trajectory " + csv + " --shards 4" + chunk_out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("chunk 3 of 4 (JOB_COMPLETION_INDEX=2 of --shards 4): frames 16..23"));
  }
  REQUIRE(runTumble("render " + kScene + kFlags + " -q --from-trajectory " + csv + " --shard 4/4" + chunk_out).exit_code == 0);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "chunks")) files += entry.is_regular_file();
  CHECK(files == kFrames);
  for (int k = 1; k <= kFrames; ++k) {
    INFO("frame " << k);
    std::string whole = fileBytes(dir / "whole" / frameName(k));
    REQUIRE(whole.size() > 1000);
    CHECK(whole == fileBytes(dir / "chunks" / frameName(k)));
  }
}

TEST_CASE("a sharded video goes per chunk, and join makes one video of every frame without re-encoding", "[scale-out]") {
  fs::path dir = freshFolder("video");
  std::string csv = simulateOnce(dir);
  for (int i = 1; i <= 4; ++i) renderVideoChunk(dir, csv, i);
  CHECK_FALSE(fs::exists(dir / "clip.mp4"));
  // Given in any order; joined in the order of their numbers.
  auto joined = runTumble("join " + (dir / "clip.mp4").string() + " " + part(dir, 3) + " " + part(dir, 1) + " " +
                          part(dir, 4) + " " + part(dir, 2));
  INFO(joined.output);
  REQUIRE(joined.exit_code == 0);
  CHECK_THAT(joined.output, Catch::Contains("joined 4 parts (31 frames)"));
  DecodedVideo whole = decodeVideo(dir / "clip.mp4");
  REQUIRE(whole.frames.size() == kFrames);
  CHECK(whole.fps == Approx(30));
  CHECK(whole.duration == Approx(kFrames / 30.0).margin(1e-3));
  std::vector<std::vector<std::uint8_t>> parts_luma;
  for (int i = 1; i <= 4; ++i) {
    DecodedVideo p = decodeVideo(part(dir, i));
    parts_luma.insert(parts_luma.end(), p.luma.begin(), p.luma.end());
  }
  CHECK(parts_luma == whole.luma);   // the coded pictures, untouched
}

TEST_CASE("with --skip-existing a re-run of a finished video chunk is a no-op, and without it the chunk is refused (73)", "[scale-out]") {
  fs::path dir = freshFolder("skip");
  std::string csv = simulateOnce(dir);
  const std::string run = "render " + kScene + kFlags + " --from-trajectory " + csv + " --shard 2/4 -o " + (dir / "clip.mp4").string();
  REQUIRE(runTumble(run + " -q").exit_code == 0);
  std::string before = fileBytes(part(dir, 2));
  auto again = runTumble(run + " --skip-existing");
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.output, Catch::Contains("nothing to do"));
  CHECK(fileBytes(part(dir, 2)) == before);
  auto refused = runTumble(run);
  CHECK(refused.exit_code == 73);
  CHECK_THAT(refused.output, Catch::Contains("clip.part-0002-of-0004.mp4"));
}

TEST_CASE("join refuses parts that are missing (65 or 66), doubled, mixed or unlike, and an existing output (73)", "[scale-out]") {
  fs::path dir = freshFolder("join_refusals");
  std::string csv = simulateOnce(dir);
  for (int i = 1; i <= 3; ++i) renderVideoChunk(dir, csv, i);
  const std::string out = (dir / "clip.mp4").string();
  auto missing = runTumble("join " + out + " " + part(dir, 1) + " " + part(dir, 2) + " " + part(dir, 3));
  CHECK(missing.exit_code == 65);
  CHECK_THAT(missing.output, Catch::Contains("part 4 of 4") && Catch::Contains("clip.part-0004-of-0004.mp4"));
  CHECK(runTumble("join " + out + " " + part(dir, 1) + " " + part(dir, 2) + " " + part(dir, 3) + " " + part(dir, 4)).exit_code == 66);
  CHECK(runTumble("join " + out + " " + part(dir, 1) + " " + part(dir, 1) + " " + part(dir, 3)).exit_code == 65);
  CHECK(runTumble("join " + out + " " + part(dir, 1) + " " + (dir / "clip.part-0002-of-0003.mp4").string()).exit_code == 65);
  // A last chunk rendered at another size cannot be copied into the same stream.
  REQUIRE(runTumble("render " + kScene + " --duration 1 --size 192x108 --samples 1 -q --from-trajectory " + csv +
                    " --shard 4/4 -o " + out).exit_code == 0);
  auto unlike = runTumble("join " + out + " " + part(dir, 1) + " " + part(dir, 2) + " " + part(dir, 3) + " " + part(dir, 4));
  CHECK(unlike.exit_code == 65);
  CHECK_THAT(unlike.output, Catch::Contains("size") && Catch::Contains("192x108"));
  CHECK_FALSE(fs::exists(out));
  std::ofstream(out) << "precious";
  CHECK(runTumble("join " + out + " " + part(dir, 1)).exit_code == 65);   // parts 2..4 missing
  fs::remove(part(dir, 4));
  renderVideoChunk(dir, csv, 4);
  auto exists = runTumble("join " + out + " " + part(dir, 1) + " " + part(dir, 2) + " " + part(dir, 3) + " " + part(dir, 4));
  CHECK(exists.exit_code == 73);
  CHECK(fileBytes(out) == "precious");
  CHECK(runTumble("join -y " + out + " " + part(dir, 1) + " " + part(dir, 2) + " " + part(dir, 3) + " " + part(dir, 4)).exit_code == 0);
}

TEST_CASE("tumble --help documents join and render's flags for chunks", "[scale-out]") {
  auto top = runTumble("--help");
  CHECK(top.exit_code == 0);
  CHECK_THAT(top.output, Catch::Contains("join"));
  auto render = runTumble("render --help");
  CHECK_THAT(render.output, Catch::Contains("--from-trajectory") && Catch::Contains("--shard") &&
                                Catch::Contains("SLURM_ARRAY_TASK_ID") && Catch::Contains("JOB_COMPLETION_INDEX"));
  auto join = runTumble("join --help");
  CHECK(join.exit_code == 0);
  CHECK_THAT(join.output, Catch::Contains("re-encoding") && Catch::Contains("65"));
}
