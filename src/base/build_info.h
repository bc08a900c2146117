// What this binary is: the project version and the git commit it was built from, for --version
// and for stamping results. Defined in a file generated at build time (cmake/build_info.cmake),
// so only that file recompiles when the commit changes.
#pragma once

namespace tumble {

// The project's VERSION from the top-level CMakeLists.txt, e.g. "0.1.0".
const char* buildVersion();
// The short commit hash, with "-dirty" when tracked files had uncommitted changes at build time;
// "unknown" when the source tree was not a git checkout (or git was not installed).
const char* buildCommit();

}  // namespace tumble
