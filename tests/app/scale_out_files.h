// Shared by the scale-out tests: the scene, fresh folders and whole-file comparison.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace tumble::test {

// The knock-down: impacts, spin and friction, so poses carry every digit a double has.
inline const std::string kKnockdown = std::string(TUMBLE_SOURCE_DIR) + "/scenes/knockdown.json";
// Frames small and quick to draw.
inline const std::string kSmallFrames = " --size 160x90 --samples 1 --shadow-map-size 256";

inline std::filesystem::path freshFolder(const std::string& name) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tumble_scale_out_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

inline std::string frameName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "f_%04d.png", k);
  return name;
}

}  // namespace tumble::test
