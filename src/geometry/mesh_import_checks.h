// Files that assimp 5.2 (Debian 12) does not return from, or would try to allocate terabytes
// for, recognised by a cheap look at their header and refused before assimp sees them. Each
// check names the file that taught it (a test file or a fuzz finding).
#pragma once

#include <filesystem>

namespace tumble {

// Throws Error(BadInput) naming `file` when it is a PLY whose header never ends, or an OFF whose
// declared vertex or face count cannot fit in its size.
void refuseFilesAssimpHangsOn(const std::filesystem::path& file);

}  // namespace tumble
