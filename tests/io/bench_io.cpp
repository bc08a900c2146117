// Times writePng and H.264 encoding of 1280x720 frames (median over 100 frames) and checks
// whether two encodes of the same frames give the same bytes. Usage: bench_io [OUT_DIR]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "io/png_file.h"
#include "io/video_writer.h"
#include "synthetic_image.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kWidth = 1280, kHeight = 720, kFrames = 100;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::vector<char> bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Returns per-frame times of write() and prints the whole-clip figure (with the final flush).
std::vector<double> encode(const fs::path& path, const std::vector<tumble::RgbImage>& frames) {
  std::vector<double> times;
  auto all = Clock::now();
  tumble::VideoWriter writer(path, tumble::VideoSettings{kWidth, kHeight, 30, 23, "veryfast"});
  for (const auto& image : frames) {
    auto start = Clock::now();
    writer.write(image);
    times.push_back(msSince(start));
  }
  writer.finish();
  std::printf("h264 whole clip incl. open+flush: %.2f ms/frame, %.0f KiB\n",
              msSince(all) / kFrames, fs::file_size(path) / 1024.0);
  return times;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path out = argc > 1 ? fs::path(argv[1]) : fs::temp_directory_path() / "tumble-bench-io";
  fs::create_directories(out);
  std::vector<tumble::RgbImage> frames;
  for (int i = 0; i < kFrames; ++i) {
    frames.push_back(tumble::test::syntheticImage(kWidth, kHeight, i));
  }

  std::vector<double> png;
  for (int i = 0; i < kFrames; ++i) {
    auto start = Clock::now();
    tumble::writePng(out / ("frame_" + std::to_string(i) + ".png"), frames[i]);
    png.push_back(msSince(start));
  }
  std::printf("writePng 1280x720: median %.2f ms/frame, %.0f KiB/frame\n", median(png),
              fs::file_size(out / "frame_0.png") / 1024.0);

  std::vector<double> h264 = encode(out / "a.mp4", frames);
  std::printf("h264 write(): median %.2f ms/frame\n", median(h264));
  encode(out / "b.mp4", frames);
  std::printf("two encodes byte-identical: %s\n",
              bytes(out / "a.mp4") == bytes(out / "b.mp4") ? "yes" : "NO");
  fs::remove_all(out);
  return 0;
}
