// render's flags for rendering in chunks: motion from a trajectory file, and which chunk.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "app/shard_selection.h"

namespace tumble {

void addScaleOutOptions(CLI::App& render, std::string& from_trajectory, ShardRequest& shard);

}  // namespace tumble
