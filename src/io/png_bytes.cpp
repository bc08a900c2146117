#include "io/png_bytes.h"

#include <cstdlib>
#include <memory>
#include <spng.h>
#include <string>

#include "base/error.h"

namespace tumble {

std::vector<std::uint8_t> encodePngBytes(const RgbaImage& image) {
  std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free);
  spng_set_option(ctx.get(), SPNG_ENCODE_TO_BUFFER, 1);
  spng_ihdr ihdr{};
  ihdr.width = static_cast<std::uint32_t>(image.width);
  ihdr.height = static_cast<std::uint32_t>(image.height);
  ihdr.bit_depth = 8;
  ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR_ALPHA;
  int err = spng_set_ihdr(ctx.get(), &ihdr);
  if (!err)
    err = spng_encode_image(ctx.get(), image.pixels.data(), image.pixels.size(), SPNG_FMT_PNG,
                            SPNG_ENCODE_FINALIZE);
  std::size_t size = 0;
  // The buffer is libspng's, allocated with malloc: copied out, then freed.
  std::unique_ptr<void, void (*)(void*)> png(err ? nullptr : spng_get_png_buffer(ctx.get(), &size, &err),
                                             std::free);
  if (err || !png)
    throw Error(ExitCode::Software, std::string("encoding a texture as PNG: ") + spng_strerror(err));
  const auto* bytes = static_cast<const std::uint8_t*>(png.get());
  return std::vector<std::uint8_t>(bytes, bytes + size);
}

}  // namespace tumble
