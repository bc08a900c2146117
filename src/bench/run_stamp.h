// What the head of the results page says about a run, so a reader can judge and reproduce its
// figures: when, with which command, at which commit and build type, on which machine, against
// which engine versions.
#pragma once

#include <string>
#include <vector>

#include "bench/machine_info.h"

namespace tumble::bench {

struct RunStamp {
  std::string date;                   // UTC, when the run started: "2026-11-24 10:02 UTC"
  std::string command;                // "tumble-bench --docs docs/bench --hz 60,240"
  std::string commit, version;        // of tumble, from the build
  std::string build_type;             // CMAKE_BUILD_TYPE: "Release"
  MachineInfo machine;
  std::vector<std::string> engines;   // "tumble 0.1.0", "Bullet 3.24", ...
};

// `args` are argv[1..]; the program is named "tumble-bench" whatever path it was started by.
RunStamp stampThisRun(const std::vector<std::string>& args);

// An argument as a POSIX shell would need it typed: quoted only when it has to be.
std::string shellQuoted(const std::string& arg);

}  // namespace tumble::bench
