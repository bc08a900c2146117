// A video rendered in chunks, one file per chunk, and joined back into one file without
// re-encoding: the packets are copied (libavformat stream copy, as ffmpeg's concat demuxer with
// -c copy does) and each chunk's timestamps shifted to follow the previous chunk's last frame.
// Chunks are named after the video and their place: out/clip.part-0003-of-0008.mp4.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

namespace tumble {

// "out/clip.mp4", 3, 8 -> "out/clip.part-0003-of-0008.mp4".
std::filesystem::path videoPartPath(const std::filesystem::path& video, int index, int count);

struct VideoPartName {
  std::filesystem::path video;   // the whole video's name: "out/clip.mp4"
  int index = 0, count = 0;
};
// The inverse of videoPartPath; none for a name not of that form.
std::optional<VideoPartName> parseVideoPartName(const std::filesystem::path& part);

struct JoinSummary {
  int parts = 0;
  long frames = 0;
};

// Writes `parts` into `output` in the order of their part numbers. Refuses (Error(BadInput), naming
// the file) parts that are not named NAME.part-I-of-N.EXT, that disagree on N or NAME, that leave a
// part out or give one twice, or whose streams differ (codec, size, pixel format, frame rate,
// time base, codec headers), since a copied stream must decode as one. A missing part is
// Error(MissingInput); an existing output without `overwrite`, or one that cannot be written, is
// Error(CantCreate). The output appears whole or not at all (written to a temporary sibling first).
JoinSummary joinVideoParts(const std::filesystem::path& output, const std::vector<std::filesystem::path>& parts,
                           bool overwrite);

}  // namespace tumble
