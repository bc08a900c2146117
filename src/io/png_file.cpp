#include "io/png_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include <spng.h>

// stb_image is compiled here, static to this file, so another module may compile its own copy
// without duplicate symbols. Only the PNG decoder is built: readPng reads PNG and nothing else.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "base/error.h"
#include "io/atomic_file.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

struct SpngFree {
  void operator()(spng_ctx* ctx) const { spng_ctx_free(ctx); }
};
struct FileClose {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// Encodes `image` into the open file; returns an empty string or the reason it failed.
std::string encodePng(std::FILE* file, const RgbImage& image) {
  std::unique_ptr<spng_ctx, SpngFree> ctx(spng_ctx_new(SPNG_CTX_ENCODER));
  if (!ctx) return "out of memory";
  // Level 1 without filters: ~4x faster than the defaults for renders, at ~1.5x the size.
  spng_set_option(ctx.get(), SPNG_IMG_COMPRESSION_LEVEL, 1);
  spng_set_option(ctx.get(), SPNG_FILTER_CHOICE, SPNG_DISABLE_FILTERING);
  spng_set_png_file(ctx.get(), file);
  spng_ihdr ihdr{};
  ihdr.width = static_cast<std::uint32_t>(image.width);
  ihdr.height = static_cast<std::uint32_t>(image.height);
  ihdr.bit_depth = 8;
  ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  spng_set_ihdr(ctx.get(), &ihdr);
  spng_set_srgb(ctx.get(), 0);   // the pixels are sRGB; say so, so viewers need not guess
  errno = 0;
  int err = spng_encode_image(ctx.get(), image.pixels.data(), image.pixels.size(), SPNG_FMT_PNG,
                              SPNG_ENCODE_FINALIZE);
  // A failed write leaves libspng in its "non-recoverable state"; the system's reason (a full
  // disk, a file size limit) is what the user can act on.
  if (err && errno != 0 && std::ferror(file)) return std::strerror(errno);
  return err ? spng_strerror(err) : "";
}

}  // namespace

void writePng(const fs::path& path, const RgbImage& image, bool overwrite) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throwCantWrite(path, "image is empty or its pixel buffer does not match its size");
  }
  fs::path temp = temporarySibling(path, "tmp");
  std::unique_ptr<std::FILE, FileClose> file(std::fopen(temp.c_str(), "wb"));
  if (!file) throwCantWrite(path, std::strerror(errno));
  std::string reason = encodePng(file.get(), image);
  // fclose reports a full disk for data still buffered, so its result counts too.
  if (std::fclose(file.release()) != 0 && reason.empty()) reason = std::strerror(errno);
  if (!reason.empty()) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throwCantWrite(path, reason);
  }
  commitFile(temp, path, overwrite);
}

RgbImage readPng(const fs::path& path) {
  std::unique_ptr<std::FILE, FileClose> file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    throw Error(ExitCode::MissingInput,
                "cannot read " + path.string() + ": " + std::strerror(errno));
  }
  int w = 0, h = 0, channels = 0;
  // Forcing 3 channels drops alpha and expands grey and palettes; 16-bit input is scaled to 8.
  stbi_uc* data = stbi_load_from_file(file.get(), &w, &h, &channels, 3);
  if (!data) {
    throw Error(ExitCode::BadInput, "cannot read " + path.string() + ": not a readable PNG (" +
                                        stbi_failure_reason() + ")");
  }
  RgbImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(data, data + static_cast<std::size_t>(w) * h * 3);
  stbi_image_free(data);
  return image;
}

}  // namespace tumble
