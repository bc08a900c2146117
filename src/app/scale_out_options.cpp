#include "app/scale_out_options.h"

namespace tumble {

void addScaleOutOptions(CLI::App& render, std::string& from_trajectory, ShardRequest& shard) {
  render.add_option("--from-trajectory", from_trajectory,
                    "Draw the motion in this CSV (written by 'tumble simulate SCENE --trajectory FILE') instead of "
                    "simulating; refused (65) if it comes from another scene or lacks a frame asked for");
  render.add_option("--shard", shard.shard,
                    "I/N: render the I-th of N contiguous chunks of the frames (from 1); a video goes to "
                    "NAME.part-000I-of-000N.mp4. Without --shard, --frames, -s or -e, a Slurm array task "
                    "(SLURM_ARRAY_TASK_ID) or a Kubernetes Indexed Job pod (JOB_COMPLETION_INDEX) picks its chunk");
  render.add_option("--shards", shard.shards, "N: the number of chunks for a Kubernetes Indexed Job (its completions)")
      ->check(CLI::PositiveNumber);
  render.add_option("--shards-env", shard.shards_env,
                    "VAR: read the number of chunks for a Kubernetes Indexed Job from this environment variable");
}

}  // namespace tumble
