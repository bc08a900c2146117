#include "render/gl_texture.h"

#include <cstring>
#include <string>
#include <vector>

#include "base/error.h"

namespace tumble::render {

GlTexture::GlTexture(const DrawTexture& image) {
  const std::size_t row = 4 * static_cast<std::size_t>(image.width);
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != row * image.height)
    throw Error(ExitCode::BadInput, "texture of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                        " pixels holds " + std::to_string(image.pixels.size()) + " bytes");
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  if (image.width > max_side || image.height > max_side)
    throw Error(ExitCode::BadInput, "texture of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                        " pixels is larger than OpenGL here allows (" + std::to_string(max_side) + ")");
  // GL's first row is t = 0, the bottom of the picture in the texture coordinates meshes use;
  // the image's first row is its top.
  std::vector<std::uint8_t> flipped(image.pixels.size());
  for (int y = 0; y < image.height; ++y)
    std::memcpy(&flipped[y * row], &image.pixels[(image.height - 1 - y) * row], row);
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               flipped.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Repeat: glTF's default wrap, and what OBJ texture coordinates beyond [0, 1] expect.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
}

GlTexture::~GlTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

void GlTexture::bind(GLenum unit) const {
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace tumble::render
