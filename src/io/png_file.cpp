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

bool printableAscii(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c > 0x7e) return false;
  return true;
}

// libspng takes the chunks as C structs pointing into `text`, which outlives the encode.
std::vector<spng_text> textChunks(const std::vector<PngText>& text) {
  std::vector<spng_text> chunks;
  for (const PngText& t : text) {
    spng_text c{};
    std::snprintf(c.keyword, sizeof c.keyword, "%s", t.keyword.c_str());
    c.type = printableAscii(t.text) ? SPNG_TEXT : SPNG_ITXT;
    c.length = t.text.size();
    c.text = const_cast<char*>(t.text.c_str());
    c.language_tag = const_cast<char*>("");
    c.translated_keyword = const_cast<char*>("");
    chunks.push_back(c);
  }
  return chunks;
}

// Encodes `image` into the open file; returns an empty string or the reason it failed.
std::string encodePng(std::FILE* file, const RgbImage& image, const std::vector<PngText>& text) {
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
  std::vector<spng_text> chunks = textChunks(text);
  if (!chunks.empty())
    if (int err = spng_set_text(ctx.get(), chunks.data(), static_cast<std::uint32_t>(chunks.size())))
      return std::string("text chunk: ") + spng_strerror(err);
  errno = 0;
  int err = spng_encode_image(ctx.get(), image.pixels.data(), image.pixels.size(), SPNG_FMT_PNG,
                              SPNG_ENCODE_FINALIZE);
  // A failed write leaves libspng in its "non-recoverable state"; the system's reason (a full
  // disk, a file size limit) is what the user can act on.
  if (err && errno != 0 && std::ferror(file)) return std::strerror(errno);
  return err ? spng_strerror(err) : "";
}

}  // namespace

void writePng(const fs::path& path, const RgbImage& image, bool overwrite, const std::vector<PngText>& text) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throwCantWrite(path, "image is empty or its pixel buffer does not match its size");
  }
  fs::path temp = temporarySibling(path, "tmp");
  std::unique_ptr<std::FILE, FileClose> file(std::fopen(temp.c_str(), "wb"));
  if (!file) throwCantWrite(path, std::strerror(errno));
  std::string reason = encodePng(file.get(), image, text);
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

std::vector<PngText> readPngText(const fs::path& path) {
  std::unique_ptr<std::FILE, FileClose> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Error(ExitCode::MissingInput, "cannot read " + path.string() + ": " + std::strerror(errno));
  std::unique_ptr<spng_ctx, SpngFree> ctx(spng_ctx_new(0));
  if (!ctx) throw Error(ExitCode::Software, "out of memory");
  spng_set_png_file(ctx.get(), file.get());
  // Text chunks may follow the pixels, so the whole file is read (the pixels are skipped by
  // decoding into a buffer of the right size, which libspng requires to reach the end).
  std::size_t size = 0;
  int err = spng_decoded_image_size(ctx.get(), SPNG_FMT_RGB8, &size);
  std::vector<unsigned char> pixels(err ? 0 : size);
  if (!err) err = spng_decode_image(ctx.get(), pixels.data(), pixels.size(), SPNG_FMT_RGB8, 0);
  std::uint32_t n = 0;
  if (!err) err = spng_get_text(ctx.get(), nullptr, &n);
  if (err == SPNG_ECHUNKAVAIL) return {};
  if (err) throw Error(ExitCode::BadInput, "cannot read " + path.string() + ": not a readable PNG (" + spng_strerror(err) + ")");
  std::vector<spng_text> chunks(n);
  spng_get_text(ctx.get(), chunks.data(), &n);
  std::vector<PngText> out;
  for (const spng_text& c : chunks) out.push_back({c.keyword, std::string(c.text, c.length)});
  return out;
}

}  // namespace tumble
