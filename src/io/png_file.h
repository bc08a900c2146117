// PNG files: written with libspng (level 1, no filter: about 4x faster than stb_image_write at its
// best, measured on this kind of machine), read with stb_image.
#pragma once

#include <filesystem>

#include "base/image.h"

namespace tumble {

// Writes atomically: to a temporary name in the same folder, then renamed. Throws
// tumble::Error(CantCreate) naming the path when it cannot. With `overwrite` false an existing
// file is never replaced (CantCreate instead), even if it appears while this frame is encoded.
void writePng(const std::filesystem::path& path, const RgbImage& image, bool overwrite = true);
// Throws tumble::Error(MissingInput) when absent, BadInput when not a readable PNG.
RgbImage readPng(const std::filesystem::path& path);

}  // namespace tumble
