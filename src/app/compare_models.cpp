#include "app/compare_models.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/camera_rig.h"
#include "app/interrupt.h"
#include "app/overlay_text.h"
#include "app/progress.h"
#include "app/scene_drawing.h"
#include "app/scene_options.h"
#include "base/error.h"
#include "dynamics/frame_record.h"
#include "dynamics/simulator.h"
#include "io/make_frame_sink.h"
#include "render/overlay_composite.h"
#include "render/renderer.h"
#include "scene/scene_overrides.h"
#include "scene/suggest.h"
#include "scene/world_builder.h"

namespace tumble {
namespace {

const std::vector<std::string>& modelNames() {
  static const std::vector<std::string> names{"baraff", "time_stepping", "penalty"};
  return names;
}

ContactModel modelOf(const std::string& name) {
  return name == "baraff" ? ContactModel::Baraff : name == "time_stepping" ? ContactModel::TimeStepping
                                                                           : ContactModel::Penalty;
}

const std::string& nameOf(ContactModel m) {
  return modelNames()[m == ContactModel::Baraff ? 0 : m == ContactModel::TimeStepping ? 1 : 2];
}

// Where the tiles go. Two models: left and right halves. Three: a 2x2 grid with the bottom-right
// cell left empty, not a row of three. A row at 1280x720 makes tiles of 427x720, taller than
// wide: a camera composed for a 16:9 frame then loses its sides or, framing to fit, draws the
// bodies a third the size. The grid keeps every tile 640x360, the frame's own shape, so each tile
// is the scene as it would be framed alone, at half size; the empty cell costs a quarter of the
// pixels, less than the row wastes above and below the bodies.
struct Layout {
  int cols = 2, rows = 1, tile_w = 0, tile_h = 0;
};

Layout layoutFor(int width, int height, int models) {
  Layout l;
  l.rows = models <= 2 ? 1 : 2;
  l.tile_w = width / l.cols;
  l.tile_h = height / l.rows;
  if (l.tile_w < 16 || l.tile_h < 16)
    throw Error(ExitCode::Usage, "--compare-models: a " + std::to_string(width) + "x" + std::to_string(height) +
                                     " frame is too small to tile; give --size a larger one");
  return l;
}

constexpr std::uint8_t kBackground[3] = {28, 30, 36};   // the empty cell and any leftover pixels

// One model's run: its motion and, per frame, what its label shows: the HUD's figures (the frame
// recorder's, overlay_render.h), the deepest contact also the fault check's of every step (what
// --stats reports), so that a contact sinking and springing back between two frames counts.
struct ModelRun {
  ContactModel model{};
  Trajectory trajectory;
  std::vector<double> deepest_so_far_m;   // per frame, the deepest contact at the end of any step up to it
  std::vector<double> total_j;            // per frame, the total energy
  std::vector<double> simulate_ms;        // per frame, mean wall ms per frame simulated up to it
  double simulate_s = 0;                  // wall, the whole run, the recording left out
  int simulated_frames = 0;
};

std::string format(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

std::string depthText(double m) {
  m = m < 1e-12 ? 0 : m;   // below a picometre: rounding
  return m < 1e-4 ? format("%.3g \u00b5m", 1e6 * m) : format("%.3g mm", 1e3 * m);
}

// "-0.01234 J (-0.5 %)": the change since the first frame, as the HUD gives it (overlay_text.cpp),
// rounding noise (below a billionth of the energies) shown as 0.
std::string driftText(double total, double start) {
  const double drift = total - start;
  if (std::abs(drift) < 1e-9 * std::max({std::abs(start), std::abs(total), 1e-300})) return "+0 J";
  return format("%+.4g J", drift) + (start != 0 ? format(" (%+.3g %%)", 100 * drift / std::abs(start)) : "");
}

ModelRun simulate(const Scene& base, ContactModel model, int last_frame, bool keep_going, bool quiet,
                  SceneDrawing* drawing) {
  Scene scene = base;
  setContactModel(scene, model, "--compare-models");
  BuiltWorld built = buildWorld(scene);
  if (drawing) {   // the first model's: every model draws the same bodies
    for (const std::string& w : built.warnings)
      if (!quiet) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
    *drawing = prepareDrawing(scene, built.world);
    for (const std::string& w : drawing->warnings)
      if (!quiet) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
  }
  SimulationPlan plan{built.step, scene.simulation.steps_per_frame, last_frame, keep_going};
  Simulator simulator(std::move(built.world), plan);
  ModelRun run;
  run.model = model;
  Progress progress("simulate " + nameOf(model), plan.frames, !quiet);
  FrameRecorder recorder(simulator.world(), plan.step);
  std::vector<ImpactMark> no_impacts;
  double recording_s = 0, deepest = 0;
  const auto start = std::chrono::steady_clock::now();
  run.trajectory = simulator.run([&](int f) {
    const double simulating_s = secondsSince(start) - recording_s;   // the recording left out
    const auto record_start = std::chrono::steady_clock::now();
    const FrameRecord r = recorder.record(simulator.world(), simulator.pipeline(), no_impacts);
    deepest = std::max({deepest, r.deepest_m, simulator.faults().extremes().deepest_m});
    run.deepest_so_far_m.push_back(deepest);
    run.total_j.push_back(r.total());
    run.simulate_ms.push_back(f > 1 ? 1e3 * simulating_s / (f - 1) : 0);
    recording_s += secondsSince(record_start);
    progress.update(f);
    stopIfInterrupted("simulating", f, plan.frames);
  });
  run.simulate_s = secondsSince(start) - recording_s;
  run.simulated_frames = plan.frames;
  progress.finish();
  reportFaults(simulator.faults());
  reportTarget(simulator, quiet);
  return run;
}

std::vector<std::string> labelLines(const ModelRun& run, int frame, bool wall_time) {
  const std::size_t k = static_cast<std::size_t>(frame - 1);
  std::vector<std::string> lines{nameOf(run.model) + format("   t %.3f s", run.trajectory.times[k]),
                                 "deepest " + depthText(run.deepest_so_far_m[k]),
                                 "drift " + driftText(run.total_j[k], run.total_j.front())};
  if (wall_time) lines.push_back(format("simulate %.2f ms/frame", run.simulate_ms[k]));
  return lines;
}

void fill(RgbImage& image, int x0, int y0, int x1, int y1, const std::uint8_t rgb[3]) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x)
      std::copy(rgb, rgb + 3, &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 3]);
}

void blit(RgbImage& frame, const RgbImage& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y)
    std::copy_n(&tile.pixels[static_cast<std::size_t>(y) * tile.width * 3], tile.width * 3,
                &frame.pixels[(static_cast<std::size_t>(y0 + y) * frame.width + x0) * 3]);
}

}  // namespace

void addCompareOptions(CLI::App& render, CompareOptions& o) {
  render.add_option("--compare-models", o.models,
                    "Render the scene under each of these contact models (two or three of baraff, time_stepping, "
                    "penalty), side by side in one video, each tile labelled with its model, deepest penetration "
                    "and energy drift")
      ->delimiter(',')
      ->type_name("MODELS");
  render.add_flag("--compare-wall-time", o.wall_time,
                  "With --compare-models: also print each model's simulate wall time per frame in its tile "
                  "(the frames then differ from run to run)");
}

std::vector<ContactModel> parseCompareModels(const CompareOptions& o,
                                             const std::vector<std::pair<std::string, bool>>& given) {
  if (!o.any()) {
    if (o.wall_time) throw Error(ExitCode::Usage, "--compare-wall-time needs --compare-models");
    return {};
  }
  std::vector<ContactModel> models;
  for (const std::string& name : o.models) {
    if (std::find(modelNames().begin(), modelNames().end(), name) == modelNames().end()) {
      std::string message = "--compare-models: unknown contact model \"" + name + "\"";
      const std::string near = closestMatch(name, modelNames());
      if (name == "auto")
        message += "; auto picks one of the others for the scene: name the models to compare";
      else if (!near.empty())
        message += "; did you mean \"" + near + "\"?";
      else
        message += "; the models are baraff, time_stepping, penalty";
      throw Error(ExitCode::Usage, message);
    }
    if (std::find(models.begin(), models.end(), modelOf(name)) != models.end())
      throw Error(ExitCode::Usage, "--compare-models: " + name + " is named twice");
    models.push_back(modelOf(name));
  }
  if (models.size() < 2)
    throw Error(ExitCode::Usage, "--compare-models: name two or three models to compare (for one, use --contact-model)");
  for (const auto& [flag, on] : given)
    if (on)
      throw Error(ExitCode::Usage, "--compare-models cannot be combined with " + flag +
                                       ": a comparison simulates each model itself, whole, and draws only its labels");
  return models;
}

void prepareComparison(Scene& scene, const std::vector<ContactModel>& models) {
  for (ContactModel m : models) {
    Scene copy = scene;
    setContactModel(copy, m, "--compare-models");   // a model the scene's settings rule out: 64, now
  }
  layoutFor(scene.render.width, scene.render.height, static_cast<int>(models.size()));   // too small: 64, now
  scene.overlays = OverlaySpec{};
}

std::string comparisonSettings(const std::vector<ContactModel>& models) {
  std::string out;
  for (ContactModel m : models) out += (out.empty() ? " compare " : ",") + nameOf(m);
  return out;
}

int renderComparison(const std::vector<ContactModel>& models, const CompareOptions& options, ComparisonJob job) {
  const Scene& scene = job.scene;
  const Layout layout = layoutFor(scene.render.width, scene.render.height, static_cast<int>(models.size()));
  const auto total_start = std::chrono::steady_clock::now();
  // A fit camera frames the whole clip, so its motion is simulated to the end whatever is rendered.
  const int last_frame = job.camera.form == CameraSpec::Form::Fit ? scene.render.frames : job.frames.back();

  SceneDrawing drawing;
  std::vector<ModelRun> runs;
  for (ContactModel m : models)
    runs.push_back(simulate(scene, m, last_frame, job.keep_going, job.quiet, runs.empty() ? &drawing : nullptr));
  double simulate_s = 0;
  for (const ModelRun& r : runs) simulate_s += r.simulate_s;

  RenderConfig config;
  config.width = layout.tile_w;
  config.height = layout.tile_h;
  config.samples = scene.render.samples;
  config.shadow_map_size = scene.render.shadow_map_size;
  config.shader_dir = job.shaders;
  std::unique_ptr<Renderer> renderer = Renderer::create(config);
  job.sink->setRenderer(renderer->glRenderer());
  const std::vector<int> mesh_ids = uploadDrawing(*renderer, drawing);

  // The same camera in every tile. A fixed or orbiting one is the scene's; one that follows or
  // looks at a body takes the first model's; a fit camera keeps every model's bodies in view.
  Trajectory all;
  all.times = runs.front().trajectory.times;
  all.frames.resize(all.times.size());
  std::vector<double> radii;
  const std::vector<double> body_radii = bodyRadii(drawing);   // the same bodies in every run
  for (const ModelRun& r : runs) {
    all.body_names.insert(all.body_names.end(), r.trajectory.body_names.begin(), r.trajectory.body_names.end());
    for (std::size_t k = 0; k < all.frames.size(); ++k)
      all.frames[k].insert(all.frames[k].end(), r.trajectory.frames[k].begin(), r.trajectory.frames[k].end());
    radii.insert(radii.end(), body_radii.begin(), body_radii.end());
  }
  const std::vector<DrawCamera> cameras =
      cameraPath(job.camera, all, radii, double(layout.tile_w) / layout.tile_h);

  const double font_px = std::max(8.0, std::round(0.8 * overlayFontPx(scene.render.height)));
  const int seam = std::max(1, scene.render.height / 360);   // a dark line between tiles
  constexpr std::uint8_t kSeam[3] = {12, 13, 16};
  Progress progress("render", static_cast<int>(job.frames.size()), !job.quiet);
  RgbImage image{scene.render.width, scene.render.height, {}}, tile;
  double render_s = 0, encode_s = 0;
  int done = 0;
  for (int frame : job.frames) {
    if (interruptRequested()) break;
    auto start = std::chrono::steady_clock::now();
    image.pixels.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0);
    fill(image, 0, 0, image.width, image.height, kBackground);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      poseInstances(drawing, runs[i].trajectory.frames[frame - 1], mesh_ids);
      drawing.frame.camera = cameras[frame - 1];
      drawing.frame.marks = DrawMarks{};
      renderer->draw(drawing.frame);
      renderer->readBack(tile);
      const OverlayPanel label = textPanel(labelLines(runs[i], frame, options.wall_time), font_px, tile.height, false);
      compositeOver(tile, label.layer, label.x, label.y);
      blit(image, tile, static_cast<int>(i % layout.cols) * layout.tile_w, static_cast<int>(i / layout.cols) * layout.tile_h);
    }
    for (int c = 1; c < layout.cols; ++c)
      fill(image, c * layout.tile_w - seam / 2 - seam % 2, 0, c * layout.tile_w + seam / 2, image.height, kSeam);
    for (int r = 1; r < layout.rows; ++r)
      fill(image, 0, r * layout.tile_h - seam / 2 - seam % 2, image.width, r * layout.tile_h + seam / 2, kSeam);
    if (runs.size() < static_cast<std::size_t>(layout.cols * layout.rows)) {   // the empty cell: the scene's name
      const OverlayPanel title = textPanel({scene.name, "contact models compared"}, font_px, layout.tile_h, false);
      const int i = static_cast<int>(runs.size());
      compositeOver(image, title.layer, (i % layout.cols) * layout.tile_w + title.x + seam,
                    (i / layout.cols) * layout.tile_h + title.y + seam);
    }
    render_s += secondsSince(start);
    start = std::chrono::steady_clock::now();
    job.sink->write(image, frame);
    encode_s += secondsSince(start);
    progress.update(++done);
  }
  const bool interrupted = done < static_cast<int>(job.frames.size());
  const std::string written = finishFrameSink(job.sink, job.target, interrupted);
  progress.finish();
  const double wall = secondsSince(total_start);
  if (!job.quiet || interrupted) {
    std::fprintf(stderr,
                 "tumble: %s %d of %zu frames comparing %zu contact models to %s in %.2f s: simulate %.2f s, "
                 "render %.2f s (%.1f ms a frame, every tile), encode %.2f s\n",
                 interrupted ? "interrupted after" : "rendered", done, job.frames.size(), runs.size(), written.c_str(),
                 wall, simulate_s, render_s, 1e3 * render_s / std::max(done, 1), encode_s);
    // Wall times vary from run to run, so they are printed here and drawn into the frames only
    // with --compare-wall-time; the frames' other figures are the simulation's own.
    for (const ModelRun& r : runs)
      std::fprintf(stderr, "  %-13s simulate %.2f ms/frame (wall, mean of %d), deepest %s, energy drift %s\n",
                   nameOf(r.model).c_str(), 1e3 * r.simulate_s / std::max(r.simulated_frames - 1, 1),
                   r.simulated_frames - 1, depthText(r.deepest_so_far_m.back()).c_str(),
                   driftText(r.total_j.back(), r.total_j.front()).c_str());
  }
  return interrupted ? static_cast<int>(ExitCode::Interrupted) : 0;
}

}  // namespace tumble
