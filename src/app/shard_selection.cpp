#include "app/shard_selection.h"

#include <charconv>
#include <cstdio>

#include "base/error.h"
#include "io/video_join.h"

namespace tumble {

namespace {

std::optional<long> integerOf(const char* text) {
  if (!text || !*text) return std::nullopt;
  long value = 0;
  const char* end = text + std::char_traits<char>::length(text);
  auto [ptr, ec] = std::from_chars(text, end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

long required(const EnvLookup& env, const char* name, const std::string& why) {
  std::optional<long> v = integerOf(env(name));
  if (!v) throw Error(ExitCode::Usage, std::string(name) + " is " + (env(name) ? "'" + std::string(env(name)) + "', not a whole number" : "not set") + why);
  return *v;
}

Shard checked(long index, long count, const std::string& source) {
  if (count < 1 || index < 1 || index > count)
    throw Error(ExitCode::Usage, source + ": chunk " + std::to_string(index) + " of " + std::to_string(count) +
                                     " does not exist (chunks count from 1 to their number)");
  return {static_cast<int>(index), static_cast<int>(count), source};
}

Shard parseShardFlag(const std::string& text) {
  std::size_t slash = text.find('/');
  std::optional<long> i = slash == std::string::npos ? std::nullopt : integerOf(text.substr(0, slash).c_str());
  std::optional<long> n = slash == std::string::npos ? std::nullopt : integerOf(text.substr(slash + 1).c_str());
  if (!i || !n) throw Error(ExitCode::Usage, "--shard '" + text + "': expected I/N, e.g. 3/8 (the 3rd of 8 chunks)");
  return checked(*i, *n, "--shard " + text);
}

// A Slurm array task: its place among the array's tasks. `--array=1-8` numbers tasks 1..8, `0-7`
// 0..7 and `1-15:2` 1,3,..,15; each is chunk (ID - MIN) / STEP + 1 of (MAX - MIN) / STEP + 1.
Shard slurmShard(const EnvLookup& env, long id) {
  const std::string why = " (a Slurm array task needs SLURM_ARRAY_TASK_MIN and _MAX, or _COUNT)";
  std::string source = "SLURM_ARRAY_TASK_ID=" + std::to_string(id);
  if (!env("SLURM_ARRAY_TASK_MIN") || !env("SLURM_ARRAY_TASK_MAX")) {
    long count = required(env, "SLURM_ARRAY_TASK_COUNT", why);
    return checked(id, count, source + " of SLURM_ARRAY_TASK_COUNT=" + std::to_string(count));
  }
  long min = required(env, "SLURM_ARRAY_TASK_MIN", why), max = required(env, "SLURM_ARRAY_TASK_MAX", why);
  long step = env("SLURM_ARRAY_TASK_STEP") ? required(env, "SLURM_ARRAY_TASK_STEP", why) : 1;
  std::string array = std::to_string(min) + "-" + std::to_string(max);   // as --array= wrote it
  if (step > 1) array.append(":").append(std::to_string(step));
  if (step < 1 || (id - min) % step != 0)
    throw Error(ExitCode::Usage, source + " is not on the array's grid " + array + "; give --shard I/N");
  long count = (max - min) / step + 1;
  if (env("SLURM_ARRAY_TASK_COUNT") && required(env, "SLURM_ARRAY_TASK_COUNT", why) != count)
    throw Error(ExitCode::Usage, "SLURM_ARRAY_TASK_COUNT=" + std::string(env("SLURM_ARRAY_TASK_COUNT")) +
                                     " does not match the array " + array + " (an array with gaps, like --array=1,4,9?): give --shard I/N");
  return checked((id - min) / step + 1, count, source + " (array " + array + ")");
}

Shard kubernetesShard(const ShardRequest& request, const EnvLookup& env, long index) {
  std::string source = "JOB_COMPLETION_INDEX=" + std::to_string(index);
  long count = 0;
  if (request.shards) {
    count = *request.shards;
    source += " of --shards " + std::to_string(count);
  } else if (!request.shards_env.empty()) {
    count = required(env, request.shards_env.c_str(), " (named by --shards-env)");
    source += " of " + request.shards_env + "=" + std::to_string(count);
  } else {
    throw Error(ExitCode::Usage, source + " is set but the number of chunks is not: give --shards N (the Job's "
                                          "completions) or --shards-env VAR");
  }
  return checked(index + 1, count, source);   // Kubernetes counts from 0
}

}  // namespace

std::optional<Shard> chooseShard(const ShardRequest& request, bool frames_chosen, const EnvLookup& env) {
  if (!request.shard.empty()) return parseShardFlag(request.shard);
  if (frames_chosen) return std::nullopt;
  if (env("SLURM_ARRAY_TASK_ID"))
    return slurmShard(env, required(env, "SLURM_ARRAY_TASK_ID", ""));
  if (env("JOB_COMPLETION_INDEX"))
    return kubernetesShard(request, env, required(env, "JOB_COMPLETION_INDEX", ""));
  if (request.shards || !request.shards_env.empty())
    throw Error(ExitCode::Usage, "--shards and --shards-env go with JOB_COMPLETION_INDEX (a Kubernetes Indexed "
                                 "Job), which is not set; give --shard I/N");
  return std::nullopt;
}

std::vector<int> shardFrames(const std::vector<int>& frames, const Shard& shard) {
  const std::size_t m = frames.size(), n = static_cast<std::size_t>(shard.count);
  if (n > m)
    throw Error(ExitCode::Usage, shard.source + ": " + std::to_string(n) + " chunks of " + std::to_string(m) +
                                     " frames would leave some chunks empty; use at most " + std::to_string(m));
  // Chunk k (from 0) takes [k*m/n, (k+1)*m/n): sizes differ by one at most.
  const std::size_t k = static_cast<std::size_t>(shard.index - 1);
  return std::vector<int>(frames.begin() + static_cast<long>(k * m / n), frames.begin() + static_cast<long>((k + 1) * m / n));
}

void useShardOutput(const Shard& shard, const std::vector<int>& frames, OutputTarget& target, bool quiet) {
  if (target.kind == OutputTarget::Kind::Video) {
    target.path = videoPartPath(target.path, shard.index, shard.count);
    target.pattern = target.path.string();
  }
  if (quiet) return;
  std::fprintf(stderr, "tumble: chunk %d of %d (%s): frames %d..%d (%zu) to %s\n", shard.index, shard.count,
               shard.source.c_str(), frames.front(), frames.back(), frames.size(),
               target.kind == OutputTarget::Kind::Video ? target.path.c_str() : target.pattern.c_str());
}

}  // namespace tumble
