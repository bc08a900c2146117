// A PNG in memory, for containers that embed images (the glTF binary's textures).
#pragma once

#include <cstdint>
#include <vector>

#include "base/image.h"

namespace tumble {

// RGBA, 8 bits per channel, as the pixels are (sRGB for a base-colour texture). Throws
// tumble::Error(Software) if libspng refuses the image (an empty one).
std::vector<std::uint8_t> encodePngBytes(const RgbaImage& image);

}  // namespace tumble
