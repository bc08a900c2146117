// Texture images: decoded whatever their format, from a file or from bytes in a mesh file, and
// refused with the file named when they are not images.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "base/error.h"
#include "io/texture_image.h"

using namespace tumble;

namespace {
const std::filesystem::path kAssets = std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests" / "assets";
}

TEST_CASE("a texture file decodes to RGBA, top row first", "[texture]") {
  const RgbaImage image = readTextureFile(kAssets / "stripes.png");
  REQUIRE(image.width == 32);
  REQUIRE(image.height == 32);
  REQUIRE(image.pixels.size() == 32 * 32 * 4);
  // Columns 0..3 are light, 4..7 red (make_visual_assets.py); alpha is opaque where the PNG has none.
  CHECK(std::vector<int>(image.pixels.begin(), image.pixels.begin() + 4) == std::vector<int>{245, 245, 240, 255});
  CHECK(std::vector<int>(image.pixels.begin() + 16, image.pixels.begin() + 20) == std::vector<int>{200, 60, 20, 255});
}

TEST_CASE("a texture held in memory decodes as the same file does", "[texture]") {
  std::ifstream in(kAssets / "stripes.png", std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  CHECK(decodeTexture(bytes, "embedded").pixels == readTextureFile(kAssets / "stripes.png").pixels);
}

TEST_CASE("a texture that is not an image, or is absent, is an error naming it", "[texture]") {
  try {
    readTextureFile(kAssets / "not_an_image.png");
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("not_an_image.png: not an image tumble can decode"));
  }
  try {
    readTextureFile(kAssets / "no_such.png");
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::MissingInput);
    CHECK_THAT(e.what(), Catch::Contains("no_such.png"));
  }
  const std::vector<std::uint8_t> truncated{0x89, 'P', 'N', 'G'};
  CHECK_THROWS_AS(decodeTexture(truncated, "cut short"), Error);
}
