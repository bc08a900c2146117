#include <catch2/catch.hpp>

#include <fstream>
#include <functional>

#include <unistd.h>

#include "base/error.h"
#include "error_code.h"
#include "io/png_file.h"
#include "synthetic_image.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;

using test::codeOf;

TEST_CASE("PNG round trip is exact", "[io][png]") {
  test::TempDir dir;
  RgbImage image = test::syntheticImage(161, 37, 3);   // odd sizes catch stride mistakes
  writePng(dir / "a.png", image);
  RgbImage back = readPng(dir / "a.png");
  CHECK(back.width == 161);
  CHECK(back.height == 37);
  CHECK(back.pixels == image.pixels);
  // only the final file remains: the temporary was renamed away
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);
}

TEST_CASE("writePng into a missing folder throws CantCreate and leaves nothing", "[io][png]") {
  test::TempDir dir;
  fs::path target = dir / "missing/a.png";
  CHECK(codeOf([&] { writePng(target, test::syntheticImage(8, 8, 0)); }) == ExitCode::CantCreate);
  CHECK_THROWS_WITH(writePng(target, test::syntheticImage(8, 8, 0)),
                    Catch::Contains(target.string()));
  CHECK(fs::is_empty(dir.path()));
}

TEST_CASE("writePng into a read-only folder throws CantCreate and leaves nothing", "[io][png]") {
  if (::geteuid() == 0) {
    WARN("skipped: root ignores folder permissions");
    return;
  }
  test::TempDir dir;
  fs::create_directory(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  CHECK(codeOf([&] { writePng(dir / "ro/a.png", test::syntheticImage(8, 8, 0)); }) ==
        ExitCode::CantCreate);
  fs::permissions(dir / "ro", fs::perms::owner_all);
  CHECK(fs::is_empty(dir / "ro"));
}

TEST_CASE("writePng without overwrite refuses an existing file", "[io][png]") {
  test::TempDir dir;
  writePng(dir / "a.png", test::syntheticImage(8, 8, 0));
  CHECK(codeOf([&] { writePng(dir / "a.png", test::syntheticImage(8, 8, 1), false); }) ==
        ExitCode::CantCreate);
  CHECK(readPng(dir / "a.png").pixels == test::syntheticImage(8, 8, 0).pixels);
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);
  writePng(dir / "a.png", test::syntheticImage(8, 8, 1), true);
  CHECK(readPng(dir / "a.png").pixels == test::syntheticImage(8, 8, 1).pixels);
}

TEST_CASE("readPng reports missing and malformed files", "[io][png]") {
  test::TempDir dir;
  CHECK(codeOf([&] { readPng(dir / "none.png"); }) == ExitCode::MissingInput);
  std::ofstream(dir / "bad.png") << "not a png";
  CHECK(codeOf([&] { readPng(dir / "bad.png"); }) == ExitCode::BadInput);
}

TEST_CASE("writePng where the folder is a file throws CantCreate", "[io][png]") {
  // Works even as root, for whom the read-only case above proves nothing.
  test::TempDir dir;
  std::ofstream(dir / "plain") << "x";
  CHECK(codeOf([&] { writePng(dir / "plain/a.png", test::syntheticImage(8, 8, 0)); }) ==
        ExitCode::CantCreate);
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);
}

TEST_CASE("text chunks written with a PNG read back in order, non-ASCII as UTF-8, pixels unchanged", "[io][png]") {
  test::TempDir dir;
  RgbImage image = test::syntheticImage(33, 17, 5);
  const std::vector<PngText> text = {{"Software", "tumble 0.1.0"}, {"tumble renderer", "llvmpipe"},
                                     {"Title", "Würfel \xe2\x86\x92 Boden"}};
  writePng(dir / "t.png", image, true, text);
  writePng(dir / "plain.png", image);
  CHECK(readPngText(dir / "t.png") == text);
  CHECK(readPngText(dir / "plain.png").empty());
  CHECK(readPng(dir / "t.png").pixels == image.pixels);
}
