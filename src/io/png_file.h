// PNG files: written with libspng (level 1, no filter: about 4x faster than stb_image_write at its
// best, measured on this kind of machine), read with stb_image.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/image.h"

namespace tumble {

// A text chunk: a keyword (1..79 Latin-1 characters) and its text.
struct PngText {
  std::string keyword, text;
  bool operator==(const PngText&) const = default;
};

// Writes atomically: to a temporary name in the same folder, then renamed. Throws
// tumble::Error(CantCreate) naming the path when it cannot. With `overwrite` false an existing
// file is never replaced (CantCreate instead), even if it appears while this frame is encoded.
// `text` goes in before the pixels: as tEXt when it is printable ASCII, else as UTF-8 iTXt.
void writePng(const std::filesystem::path& path, const RgbImage& image, bool overwrite = true,
              const std::vector<PngText>& text = {});
// The text chunks (tEXt, zTXt, iTXt) of a PNG, in file order. Throws like readPng.
std::vector<PngText> readPngText(const std::filesystem::path& path);
// Throws tumble::Error(MissingInput) when absent, BadInput when not a readable PNG.
RgbImage readPng(const std::filesystem::path& path);

}  // namespace tumble
