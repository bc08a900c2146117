// Texture images (a mesh's base-colour map) decoded with stb_image: PNG, JPEG, BMP, TGA and the
// other formats it reads, from a file beside the mesh or from bytes embedded in the mesh file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "base/image.h"

namespace tumble {

// The largest side decoded: llvmpipe's largest texture (GL_MAX_TEXTURE_SIZE is 16384 there).
constexpr int kMaxTextureSide = 16384;

// Throws tumble::Error: MissingInput when the file is absent or unreadable, BadInput when it is
// not an image stb_image can decode or is larger than kMaxTextureSide; messages name the file.
RgbaImage readTextureFile(const std::filesystem::path& file);
// The same for an image held in memory; `label` names it in messages.
RgbaImage decodeTexture(std::span<const std::uint8_t> bytes, const std::string& label);

}  // namespace tumble
