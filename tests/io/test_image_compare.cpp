// The numbers `tumble diff` reports and decides on, on small synthetic pictures.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/image_compare.h"
#include "synthetic_image.h"

using tumble::compareImages;
using tumble::CompareSettings;
using tumble::RgbImage;

namespace {

std::uint8_t* pixel(RgbImage& image, int x, int y) {
  return &image.pixels[3 * (static_cast<std::size_t>(y) * image.width + x)];
}

}  // namespace

TEST_CASE("identical images pass with zero difference and infinite PSNR", "[compare]") {
  RgbImage a = tumble::test::syntheticImage(64, 48, 3);
  auto r = compareImages(a, a, CompareSettings{0, 0.0});
  CHECK(r.pass);
  CHECK(r.max_diff == 0);
  CHECK(r.failing == 0);
  CHECK(r.pixels == 64 * 48);
  CHECK(std::isinf(r.psnr_db));
}

TEST_CASE("a pixel fails when any channel differs by more than the threshold", "[compare]") {
  RgbImage a = tumble::test::syntheticImage(64, 48, 3), b = a;
  pixel(b, 10, 20)[2] = static_cast<std::uint8_t>(pixel(a, 10, 20)[2] ^ 0x10);   // one channel, by 16
  pixel(b, 11, 20)[0] = static_cast<std::uint8_t>(pixel(a, 11, 20)[0] ^ 0x04);   // by 4
  auto strict = compareImages(a, b, CompareSettings{0, 0.0});
  CHECK(strict.max_diff == 16);
  CHECK(strict.failing == 2);
  CHECK_FALSE(strict.pass);
  CHECK(strict.psnr_db == Approx(10 * std::log10(255.0 * 255.0 * 3 * 64 * 48 / (16 * 16 + 4 * 4))));
  CHECK(compareImages(a, b, CompareSettings{4, 0.0}).failing == 1);   // "exceeds": 4 is within 4
  CHECK(compareImages(a, b, CompareSettings{16, 0.0}).pass);
}

TEST_CASE("max_fail is the share of failing pixels allowed", "[compare]") {
  RgbImage a = tumble::test::syntheticImage(100, 10, 0), b = a;   // 1000 pixels
  for (int x = 0; x < 5; ++x) pixel(b, x, 0)[1] = static_cast<std::uint8_t>(pixel(a, x, 0)[1] ^ 0x80);
  auto r = compareImages(a, b, CompareSettings{8, 0.005});
  CHECK(r.failShare() == Approx(0.005));
  CHECK(r.pass);   // exactly at the limit passes
  CHECK_FALSE(compareImages(a, b, CompareSettings{8, 0.004}).pass);
}

TEST_CASE("images of different sizes are not compared", "[compare]") {
  RgbImage a = tumble::test::syntheticImage(64, 48, 0), b = tumble::test::syntheticImage(48, 64, 0);
  auto r = compareImages(a, b, CompareSettings{255, 1.0});
  CHECK_FALSE(r.same_size);
  CHECK_FALSE(r.pass);
  CHECK(tumble::describeSize(a) == "64x48");
}

TEST_CASE("the diff image marks failing pixels in magenta over a faded grey A", "[compare]") {
  RgbImage a = tumble::test::syntheticImage(64, 48, 0), b = a;
  pixel(b, 5, 6)[0] = static_cast<std::uint8_t>(pixel(a, 5, 6)[0] ^ 0x40);
  RgbImage d = tumble::diffImage(a, b, 8);
  REQUIRE(d.width == 64);
  REQUIRE(d.height == 48);
  const std::uint8_t* marked = pixel(d, 5, 6);
  CHECK((marked[0] == 255 && marked[1] == 0 && marked[2] == 255));
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x == 5 && y == 6) continue;
      const std::uint8_t* p = pixel(d, x, y);
      REQUIRE((p[0] == p[1] && p[1] == p[2] && p[0] >= 160));   // grey, faded towards white
    }
  }
}
