// Outputs appear whole or not at all: every file tumble writes goes to a hidden temporary sibling
// first and is renamed onto its final name only when complete. A rename within one folder is atomic
// on POSIX file systems, so a reader (or a resumed render) never sees half a frame.
#pragma once

#include <filesystem>
#include <string_view>

namespace tumble {

// ".NAME.TAG-PID" next to `final_path`. With `keep_extension`, the extension is repeated at the
// end (".drop.mp4.partial-123.mp4") so tools that guess the format from the name still can.
std::filesystem::path temporarySibling(const std::filesystem::path& final_path,
                                       std::string_view tag, bool keep_extension = false);

// Renames `temp` onto `final_path`. Without `overwrite` an existing final file is never replaced,
// even one created by another process in the meantime (renameat2 RENAME_NOREPLACE); with it, only
// a regular file (or a link) is (checkReplaceable). On failure the
// temporary file is removed and Error(CantCreate) names the final path.
void commitFile(const std::filesystem::path& temp, const std::filesystem::path& final_path,
                bool overwrite);

// Whether `path` names a stream rather than a file: "-" (standard output), or an existing
// character device, pipe or socket, following symbolic links (/dev/stdout, /dev/null, a named
// pipe). A stream is written in place: there is no file to keep whole, and renaming onto its name
// would replace the device node or the link itself.
bool isStreamOutput(const std::filesystem::path& path);

// Error(CantCreate) when an output's name is taken by something no output may replace, even with
// --overwrite: a folder, a device, a pipe (a symbolic link to a regular file is replaceable).
void checkReplaceable(const std::filesystem::path& path);

// Writes `data` to a temporary sibling and commits it (commitFile): a small output made in memory
// (a stats file, a glTF) appears whole or not at all.
void writeFileWhole(const std::filesystem::path& path, std::string_view data, bool overwrite);

// Error(CantCreate) "cannot write PATH: REASON", the one wording for unwritable outputs.
[[noreturn]] void throwCantWrite(const std::filesystem::path& path, std::string_view reason);

}  // namespace tumble
