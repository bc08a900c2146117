// How the user's `-o` becomes output files, following Blender and ffmpeg:
//   out.mp4 | out.mkv | out.mov      one video
//   out/  (or an existing folder)    out/frame_####.png
//   out/f_####.png  (any run of #)   PNG sequence, zero-padded to the number of #
//   out/f_%04d.png  | out/f_%d.png   the same in printf spelling
//   shot.png                         that file, when exactly one frame is rendered
// Frames are numbered from 1; numbers wider than the padding simply grow (frame_10000.png).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tumble {

struct OutputTarget {
  enum class Kind { PngSequence, Video };
  Kind kind = Kind::Video;
  // Video: the file. PngSequence: the pattern with the number as a run of `pad` '#'
  // ("out/frame_####.png"), or the single file itself when pad == 0.
  std::filesystem::path path;
  // The same pattern in printf/ffmpeg spelling ("out/frame_%04d.png"), ready for
  // `ffmpeg -framerate 30 -i PATTERN`. Video: the file name again.
  std::string pattern;
  // Digits of zero padding for the frame number; 0 means a single file without a number.
  int pad = 0;
};

// Throws Error(Usage) for outputs tumble cannot write, saying which forms work.
OutputTarget parseOutput(const std::string& arg, int frame_count);

// The file of one frame (frame numbers count from 1). For a video, the video file.
std::filesystem::path framePath(const OutputTarget& target, int frame_number);

// The outputs that already exist among those `frames` would produce, for refusing to overwrite
// (or skipping) before any work is done. A video counts as one output, whatever the frames.
std::vector<std::filesystem::path> existingOutputs(const OutputTarget& target,
                                                   const std::vector<int>& frames);

}  // namespace tumble
