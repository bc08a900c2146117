// libFuzzer target: any bytes as a scene file. The loader must either return a scene within the
// documented bounds or throw tumble::Error naming the file; anything else (a crash, a sanitizer
// report, another exception, a scene outside its bounds) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/error.h"
#include "scene/scene_loader.h"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_scene_loader: %s\n", what.c_str());
  std::abort();
}

void checkBounds(const tumble::Scene& s) {
  if (s.bodies.empty()) finding("a scene without bodies was accepted");
  if (s.render.frames < 1 || s.render.frames > 1000000) finding("frame count out of bounds");
  if (s.render.width < 16 || s.render.width > 8192 || s.render.height < 16 || s.render.height > 8192)
    finding("frame size out of bounds");
  if (!(s.simulation.step.dt > 0) || s.simulation.steps_per_frame < 1) finding("bad step");
  for (const tumble::BodySpec& b : s.bodies)
    if (!b.position_m.allFinite() || !b.velocity_m_s.allFinite() || !b.orientation.coeffs().allFinite())
      finding("a body with a non-finite state was accepted");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    checkBounds(tumble::parseScene(text, "fuzz/scene.json"));
  } catch (const tumble::Error& e) {
    if (std::string(e.what()).rfind("fuzz/scene.json", 0) != 0) finding(std::string("unlocated error: ") + e.what());
  }
  return 0;
}
