// Every frame says where it came from (PNG text chunks), a video too (container metadata), and
// tumble diff shows it when two frames' provenance differs.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>

extern "C" {
#include <libavformat/avformat.h>
}

#include "io/png_file.h"
#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

fs::path freshDir(const std::string& name) { return tumble::test::freshTempDir("tumble_provenance_" + name); }

std::map<std::string, std::string> textOf(const fs::path& png) {
  std::map<std::string, std::string> out;
  for (const tumble::PngText& t : tumble::readPngText(png)) out[t.keyword] = t.text;
  return out;
}

std::map<std::string, std::string> videoTags(const fs::path& video) {
  AVFormatContext* format = nullptr;
  std::map<std::string, std::string> out;
  if (avformat_open_input(&format, video.c_str(), nullptr, nullptr) < 0) return out;
  const AVDictionaryEntry* e = nullptr;
  while ((e = av_dict_get(format->metadata, "", e, AV_DICT_IGNORE_SUFFIX))) out[e->key] = e->value;
  avformat_close_input(&format);
  return out;
}

}  // namespace

TEST_CASE("every PNG carries version, commit, scene hash, frame, instant and renderer", "[cli][provenance]") {
  fs::path dir = freshDir("png");
  REQUIRE(runTumble("render -q " + kScene + " --frames 1,5 -o " + (dir / "a/").string()).exit_code == 0);
  auto first = textOf(dir / "a" / "frame_0001.png"), fifth = textOf(dir / "a" / "frame_0005.png");
  const std::string version = runTumble("--version").output;
  CHECK_THAT(version, Catch::Contains(fifth["tumble version"]) && Catch::Contains(fifth["tumble commit"]));
  CHECK(fifth["Software"].rfind("tumble " + fifth["tumble version"], 0) == 0);
  CHECK(first["tumble frame"] == "1");
  CHECK(fifth["tumble frame"] == "5");
  CHECK(first["tumble time s"] == "0");
  CHECK(fifth["tumble time s"] == "0.4");   // 10 fps: frame 5 shows t = 4/10 s
  CHECK(fifth["tumble scene hash"].size() == 16);
  CHECK(fifth["tumble scene hash"] == first["tumble scene hash"]);
  CHECK(!fifth["tumble renderer"].empty());
}

TEST_CASE("the scene hash follows the resolved scene, overrides included", "[cli][provenance]") {
  fs::path dir = freshDir("hash");
  const std::string render = "render -q " + kScene + " --frames 1 -o ";
  REQUIRE(runTumble(render + (dir / "a/").string()).exit_code == 0);
  REQUIRE(runTumble(render + (dir / "b/").string()).exit_code == 0);
  REQUIRE(runTumble(render + (dir / "c/").string() + " --set bodies.box.color=#10e040").exit_code == 0);
  REQUIRE(runTumble(render + (dir / "d/").string() + " --dt 0.005").exit_code == 0);
  const std::string a = textOf(dir / "a" / "frame_0001.png")["tumble scene hash"];
  CHECK(a == textOf(dir / "b" / "frame_0001.png")["tumble scene hash"]);
  CHECK(a != textOf(dir / "c" / "frame_0001.png")["tumble scene hash"]);
  CHECK(a != textOf(dir / "d" / "frame_0001.png")["tumble scene hash"]);
}

TEST_CASE("a video's metadata carries the version and the scene hash", "[cli][provenance]") {
  fs::path dir = freshDir("video");
  REQUIRE(runTumble("render -q " + kScene + " -o " + (dir / "clip.mp4").string()).exit_code == 0);
  REQUIRE(runTumble("render -q " + kScene + " --frames 1 -o " + (dir / "f/").string()).exit_code == 0);
  auto tags = videoTags(dir / "clip.mp4");
  auto png = textOf(dir / "f" / "frame_0001.png");
  CHECK(tags["tumble_version"] == png["tumble version"]);
  CHECK(tags["tumble_commit"] == png["tumble commit"]);
  CHECK(tags["tumble_scene_hash"] == png["tumble scene hash"]);
  CHECK_THAT(tags["comment"], Catch::Contains(png["tumble scene hash"]));
}

TEST_CASE("tumble diff prints the provenance of two frames when it differs, and not when it agrees", "[cli][provenance]") {
  fs::path dir = freshDir("diff");
  const std::string render = "render -q " + kScene + " --frames 3 -o ";
  REQUIRE(runTumble(render + (dir / "a/").string()).exit_code == 0);
  REQUIRE(runTumble(render + (dir / "b/").string()).exit_code == 0);
  // crf shapes only a video: the frames' pixels agree, their scenes do not.
  REQUIRE(runTumble(render + (dir / "c/").string() + " --set render.crf=30").exit_code == 0);
  auto same = runTumble("diff " + (dir / "a").string() + " " + (dir / "b").string());
  CHECK(same.exit_code == 0);
  CHECK_THAT(same.output, !Catch::Contains("provenance"));
  auto other = runTumble("diff " + (dir / "a").string() + " " + (dir / "c").string());
  CHECK(other.exit_code == 0);   // the pixels are the same
  CHECK_THAT(other.output, Catch::Contains("frame_0003.png: provenance differs (A | B):") &&
                               Catch::Contains("  tumble scene hash: " +
                                               textOf(dir / "a" / "frame_0003.png")["tumble scene hash"] + " | "));
  CHECK_THAT(other.output, !Catch::Contains("tumble frame:"));   // only what differs
}
