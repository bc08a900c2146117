#include "io/texture_image.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

// A second, file-static copy of stb_image (png_file.cpp holds one built for PNG only): textures
// come in every format a mesh file may name, so this one keeps all of stb_image's decoders.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb_image.h>

#include "base/error.h"

namespace tumble {

RgbaImage decodeTexture(std::span<const std::uint8_t> bytes, const std::string& label) {
  const auto* data = bytes.data();
  const int size = static_cast<int>(std::min<std::size_t>(bytes.size(), 0x7fffffff));
  int w = 0, h = 0, channels = 0;
  // Asked before decoding, so a corrupt header claiming 60000^2 pixels never allocates 14 GB.
  if (!stbi_info_from_memory(data, size, &w, &h, &channels))
    throw Error(ExitCode::BadInput, label + ": not an image tumble can decode (" + stbi_failure_reason() + ")");
  if (w > kMaxTextureSide || h > kMaxTextureSide)
    throw Error(ExitCode::BadInput, label + ": " + std::to_string(w) + "x" + std::to_string(h) +
                                        " is larger than the renderer takes (" + std::to_string(kMaxTextureSide) +
                                        " a side)");
  stbi_uc* pixels = stbi_load_from_memory(data, size, &w, &h, &channels, 4);
  if (!pixels)
    throw Error(ExitCode::BadInput, label + ": not an image tumble can decode (" + stbi_failure_reason() + ")");
  RgbaImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return image;
}

RgbaImage readTextureFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw Error(ExitCode::MissingInput, file.string() + ": no such texture file");
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  if (!in && !in.eof()) throw Error(ExitCode::MissingInput, file.string() + ": cannot be read: " + std::strerror(errno));
  return decodeTexture(bytes, file.string());
}

}  // namespace tumble
