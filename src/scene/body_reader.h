// The parts of a scene file that need more than one field read: bodies, orientations, enums.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/object_reader.h"
#include "scene/scene.h"

namespace tumble {

// Reads one entry of "bodies". Mesh paths are resolved against `scene_dir` and must exist.
BodySpec readBody(ObjectReader& in, int index, const std::filesystem::path& scene_dir);

// An orientation from "quat_wxyz" (normalised; must not be zero) or "rotation_deg" with
// "rotation_order" (extrinsic, as Blender's Euler modes: "XYZ" rotates about world x, then y,
// then z). Neither given: identity. Both: an error.
Eigen::Quaterniond readOrientation(ObjectReader& in);

// One of a closed set of strings, with "did you mean" on a miss.
std::string readChoice(ObjectReader& in, const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& choices);

// Refuses control characters (NUL above all) in a path written in the scene.
void checkPathText(ObjectReader& in, const std::string& key, const std::string& path);

// "draw": "visual" | "hulls".
BodyDraw readBodyDraw(ObjectReader& in, BodyDraw fallback);

Integrator readIntegrator(ObjectReader& in, const std::string& key, Integrator fallback);

}  // namespace tumble
