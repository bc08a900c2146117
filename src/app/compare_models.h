// render --compare-models baraff,time_stepping,penalty: the scene simulated under each contact
// model (each its own trajectory, as --contact-model would run it), drawn through the same camera
// into tiles of one video or PNG sequence, each tile labelled with its model and running figures.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/frame_sink.h"
#include "io/output_path.h"
#include "scene/scene.h"

namespace tumble {

struct CompareOptions {
  std::vector<std::string> models;   // --compare-models; empty: no comparison
  bool wall_time = false;            // --compare-wall-time: draw the simulate time into the tiles
  bool any() const { return !models.empty(); }
};

void addCompareOptions(CLI::App& render, CompareOptions& options);

// Before any work: the names (two or three of baraff, time_stepping, penalty, each once; an unknown
// one with "did you mean"), and no flag a comparison cannot honour: `given` pairs each such flag
// with whether it was given. Throws Error(Usage) (64).
std::vector<ContactModel> parseCompareModels(const CompareOptions& options,
                                             const std::vector<std::pair<std::string, bool>>& given);

// After the scene is read: each model must suit the scene (setContactModel's checks) and the frame
// must be large enough to tile; the scene's own overlays are left out (the tiles carry their own
// labels).
void prepareComparison(Scene& scene, const std::vector<ContactModel>& models);

// What the frames' provenance hashes beside the camera (frame_provenance.h), so that a comparison's
// frames never pass for a single model's: " compare baraff,penalty"; "" without a comparison.
std::string comparisonSettings(const std::vector<ContactModel>& models);

struct ComparisonJob {
  const Scene& scene;
  const CameraSpec& camera;
  std::vector<int> frames;     // to render, from 1, ascending, not empty
  OutputTarget target;
  std::unique_ptr<FrameSink> sink;
  std::string shaders;          // --shaders; empty: the built-in GLSL
  bool quiet = false, verbose = false, keep_going = false;
};

// Simulates each model, renders the tiled frames into the sink and finishes it; prints the summary
// (each model's simulate wall time per frame, deepest penetration and energy drift). Returns the
// exit code (0, or 130 when interrupted).
int renderComparison(const std::vector<ContactModel>& models, const CompareOptions& options, ComparisonJob job);

}  // namespace tumble
