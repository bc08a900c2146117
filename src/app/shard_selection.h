// Which contiguous chunk of the frame list this process renders, so one command line serves every
// task of a job array: --shard I/N, or a scheduler's task index read from the environment.
//   Slurm job array:           SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_MIN and _MAX (and _STEP),
//                              or SLURM_ARRAY_TASK_COUNT; `sbatch --array=1-8` gives chunks 1..8 of 8
//   Kubernetes Indexed Job:    JOB_COMPLETION_INDEX (0-based), with the job's completions given by
//                              --shards N or by the variable --shards-env names
// Chunks count from 1; their sizes differ by one frame at most.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/output_path.h"

namespace tumble {

struct Shard {
  int index = 1, count = 1;   // the index-th of count chunks, 1 <= index <= count
  std::string source;         // what chose it: "--shard 3/8", "SLURM_ARRAY_TASK_ID=3 (array 1-8)", ...
};

struct ShardRequest {
  std::string shard;            // --shard I/N; empty: none given
  std::optional<int> shards;    // --shards N: the count for JOB_COMPLETION_INDEX
  std::string shards_env;       // --shards-env VAR: the variable holding that count
};

using EnvLookup = std::function<const char*(const char*)>;

// The chunk to render, or none for the whole list. The environment is read only when neither
// --shard nor an explicit frame choice (`frames_chosen`: --frames, -s, -e) was given. Throws
// Error(Usage) for a malformed --shard, inconsistent variables, or an index without a count.
std::optional<Shard> chooseShard(const ShardRequest& request, bool frames_chosen, const EnvLookup& env);

// The chunk's frames: contiguous, in order. Throws Error(Usage) when the chunk would be empty
// (more chunks than frames).
std::vector<int> shardFrames(const std::vector<int>& frames, const Shard& shard);

// A sharded run's video goes per chunk, NAME.part-0003-of-0008.mp4 (tumble join puts them
// together); PNG frames keep their numbers. Says which chunk this is on stderr unless `quiet`.
void useShardOutput(const Shard& shard, const std::vector<int>& frames, OutputTarget& target, bool quiet);

}  // namespace tumble
