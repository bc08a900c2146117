#include "scene/motion_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/error.h"
#include "base/fnv1a.h"
#include "scene/object_reader.h"

namespace tumble {

namespace {

// The hash of one part, then a separator, so "ab"+"c" differs from "a"+"bc".
void addPart(Fnv1a64& fnv, const std::string& bytes) {
  fnv.add(bytes);
  fnv.addByte(0xff);
}

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ExitCode::MissingInput, "cannot read " + path.string());
  std::ostringstream all;
  all << in.rdbuf();
  return all.str();
}

// The file's JSON without the parts that only change the picture. The loader has already
// validated the file, so this parse cannot fail on a scene that loaded.
std::string motionJson(const std::string& text) {
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  for (const char* key : {"camera", "cameras", "lights", "output", "overlay_bodies", "overlays", "render"}) doc.erase(key);
  if (doc.contains("bodies") && doc["bodies"].is_array())
    for (nlohmann::json& body : doc["bodies"])
      if (body.is_object()) {
        for (const char* key : {"colour", "color", "draw"}) body.erase(key);
      }
  return doc.dump();   // keys sorted, numbers in their shortest exact form
}

}  // namespace

std::string motionHash(const Scene& scene) {
  Fnv1a64 fnv;
  // The JSON after --set and --patch when the loader kept it: an override that changes the motion
  // must change the hash.
  addPart(fnv, motionJson(scene.resolved_json.empty() ? readAll(scene.file) : scene.resolved_json));
  const StepSettings& step = scene.simulation.step;
  addPart(fnv, "fps=" + std::to_string(scene.render.fps) + " steps_per_frame=" +
          std::to_string(scene.simulation.steps_per_frame) + " dt=" + formatNumber(step.dt) +
          " integrator=" + std::to_string(static_cast<int>(step.integrator)) +
          " model=" + std::to_string(static_cast<int>(step.model)) +
          " sleep=" + std::to_string(step.sleep.enabled));
  for (const BodySpec& body : scene.bodies)
    if (!body.mesh.empty()) addPart(fnv, readAll(body.mesh));
  return fnv.hex();
}

}  // namespace tumble
