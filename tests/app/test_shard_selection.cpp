// Which chunk of the frames a process renders: --shard I/N, Slurm array variables, Kubernetes
// Indexed Job variables.
#include <catch2/catch.hpp>

#include <map>
#include <numeric>

#include "../io/error_code.h"
#include "app/shard_selection.h"

using namespace tumble;
using test::codeOf;

namespace {

using Env = std::map<std::string, std::string>;

EnvLookup lookup(const Env& env) {
  return [&env](const char* name) -> const char* {
    auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  };
}

std::vector<int> range(int first, int last) {
  std::vector<int> v(static_cast<std::size_t>(last - first + 1));
  std::iota(v.begin(), v.end(), first);
  return v;
}

}  // namespace

TEST_CASE("chunks are contiguous, in order, cover every frame once and differ in size by one at most", "[shard]") {
  for (int m : {1, 7, 10, 120, 121}) {
    std::vector<int> frames = range(3, 2 + m);
    for (int n = 1; n <= std::min(m, 9); ++n) {
      std::vector<int> joined;
      std::size_t smallest = frames.size(), largest = 0;
      for (int i = 1; i <= n; ++i) {
        std::vector<int> chunk = shardFrames(frames, {i, n, "test"});
        smallest = std::min(smallest, chunk.size());
        largest = std::max(largest, chunk.size());
        joined.insert(joined.end(), chunk.begin(), chunk.end());
      }
      INFO(m << " frames in " << n << " chunks");
      CHECK(joined == frames);
      CHECK(largest - smallest <= 1);
    }
  }
  CHECK(shardFrames(range(1, 120), {3, 8, "test"}) == range(31, 45));
  CHECK(codeOf([] { shardFrames(range(1, 3), {1, 4, "test"}); }) == ExitCode::Usage);   // a chunk would be empty
}

TEST_CASE("the flag --shard I/N counts from 1 and refuses what is not a chunk", "[shard]") {
  Env env{{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}};
  std::optional<Shard> s = chooseShard({"3/8", {}, ""}, false, lookup(env));   // the flag wins over the environment
  REQUIRE(s);
  CHECK(s->index == 3);
  CHECK(s->count == 8);
  for (const char* bad : {"0/8", "9/8", "3", "3/", "/8", "a/b", "3/8x", "-1/8"})
    CHECK(codeOf([&] { chooseShard({bad, {}, ""}, false, lookup({})); }) == ExitCode::Usage);
}

TEST_CASE("a Slurm array task picks its chunk from SLURM_ARRAY_TASK_ID and the array's bounds", "[shard]") {
  auto pick = [](const Env& env) { return chooseShard({}, false, lookup(env)); };
  std::optional<Shard> s = pick({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "8"}});
  REQUIRE(s);
  CHECK((s->index == 3 && s->count == 8));
  CHECK_THAT(s->source, Catch::Contains("SLURM_ARRAY_TASK_ID=3"));
  s = pick({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "3"},
            {"SLURM_ARRAY_TASK_COUNT", "4"}});
  CHECK((s->index == 1 && s->count == 4));
  s = pick({{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "7"},
            {"SLURM_ARRAY_TASK_STEP", "2"}});   // --array=1-7:2 is tasks 1,3,5,7
  CHECK((s->index == 3 && s->count == 4));
  s = pick({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  CHECK((s->index == 2 && s->count == 4));
  // --array=1,4,9: three tasks, but bounds that say nine; the count cannot be trusted.
  CHECK(codeOf([&] { pick({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "9"},
                           {"SLURM_ARRAY_TASK_COUNT", "3"}}); }) == ExitCode::Usage);
  CHECK(codeOf([&] { pick({{"SLURM_ARRAY_TASK_ID", "4"}}); }) == ExitCode::Usage);
  CHECK(codeOf([&] { pick({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}); }) == ExitCode::Usage);
}

TEST_CASE("a Kubernetes Indexed Job pod picks chunk JOB_COMPLETION_INDEX + 1 of --shards or a named variable", "[shard]") {
  Env env{{"JOB_COMPLETION_INDEX", "0"}, {"RENDER_CHUNKS", "4"}};
  std::optional<Shard> s = chooseShard({"", 4, ""}, false, lookup(env));
  REQUIRE(s);
  CHECK((s->index == 1 && s->count == 4));
  s = chooseShard({"", {}, "RENDER_CHUNKS"}, false, lookup(env));
  CHECK((s->index == 1 && s->count == 4));
  CHECK(codeOf([&] { chooseShard({}, false, lookup(env)); }) == ExitCode::Usage);   // no count
  CHECK(codeOf([&] { chooseShard({"", 4, ""}, false, lookup({{"JOB_COMPLETION_INDEX", "4"}})); }) == ExitCode::Usage);
  CHECK(codeOf([&] { chooseShard({"", 4, ""}, false, lookup({})); }) == ExitCode::Usage);   // --shards without an index
}

TEST_CASE("without --shard, chosen frames or a scheduler's variables, the whole list is rendered", "[shard]") {
  CHECK_FALSE(chooseShard({}, false, lookup({})));
  CHECK_FALSE(chooseShard({}, true, lookup({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})));
}
