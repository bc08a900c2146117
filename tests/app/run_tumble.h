// Runs the real tumble executable as a user would, capturing its exit code and output.
#pragma once

#include <filesystem>
#include <string>

namespace tumble::test {

struct RunResult {
  int exit_code = -1;
  std::string output;   // stdout and stderr together
};

// `args` is appended to the executable's path and run through the shell.
RunResult runTumble(const std::string& args);

// An empty folder of this name under the system's temporary folder, emptied if it was there.
std::filesystem::path freshTempDir(const std::string& name);

}  // namespace tumble::test
