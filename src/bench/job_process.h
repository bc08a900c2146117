// Each (scene, engine setting) runs in a child process: a peer that aborts (MuJoCo's mju_error
// exits the process) costs only its own rows, and every pile run's peak memory is its own.
#pragma once

#include <vector>

#include "bench/run_point.h"

namespace tumble::bench {

// Runs every dt of `scene` with `setting` in a forked child and returns one result per dt; a
// child that dies leaves failed results naming its exit status.
std::vector<RunResult> runJobInChild(const BenchScene& scene, const EngineSetting& setting,
                                     const RunOptions& options);

// The line format the child sends back (tab-separated; metrics as name=value;...). Exposed for
// the tests.
std::string encodeResult(const RunResult& r);
RunResult decodeResult(const std::string& line);

}  // namespace tumble::bench
