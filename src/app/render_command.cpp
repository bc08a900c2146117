// tumble render SCENE [-o out.mp4 | -o 'out/frame_####.png'] ...
#include <algorithm>
#include <cstdio>
#include <memory>

#include "app/camera_rig.h"
#include "app/compare_models.h"
#include "app/commands.h"
#include "app/frame_check.h"
#include "app/frame_provenance.h"
#include "app/frame_selection.h"
#include "app/interrupt.h"
#include "app/overlay_options.h"
#include "app/overlay_render.h"
#include "app/pipeline_stats.h"
#include "app/progress.h"
#include "app/render_dry_run.h"
#include "app/scene_drawing.h"
#include "app/scale_out_options.h"
#include "app/scene_options.h"
#include "app/stats_file.h"
#include "app/shard_selection.h"
#include "app/trajectory_source.h"
#include "base/error.h"
#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "io/atomic_file.h"
#include "io/make_frame_sink.h"
#include "io/output_path.h"
#include "render/renderer.h"
#include "scene/scene_overrides.h"

namespace tumble {
namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string output, size, frames, shaders, camera;
  std::optional<int> start, end, crf, samples, shadow_map_size;
  bool overwrite = false, skip_existing = false, dry_run = false;
  std::string check_against;   // folder of approved frames; empty: no check
  std::string stats;           // --stats FILE.json; empty: none
  std::string from_trajectory;  // motion from this CSV instead of simulating; empty: simulate
  std::vector<std::string> overlays;   // --overlay, beside the scene's "overlays"
  ShardRequest shard;
  CheckOptions check;
  CompareOptions compare;   // --compare-models: each model in a tile of its own (compare_models.h)
};

// Wall time of each phase, for the closing summary.
struct PhaseTimes {
  double simulate = 0, render = 0, read_back = 0, encode = 0;
  std::vector<double> render_ms, read_back_ms, encode_ms;   // per frame, for -v medians
  // Part of render: the overlays' marks built and their text drawn, per frame (the GL drawing of
  // the marks is inside the renderer's draw and not told apart). Measured directly: the
  // difference of two renders, with and without overlays, is lost in a shared machine's noise.
  double overlays = 0;
  std::vector<double> overlays_ms;
};

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void printMedians(const PhaseTimes& t, double simulate_ms_per_frame) {
  std::fprintf(stderr,
               "  per frame (median): simulate %.2f ms (mean), render %.2f ms, read back %.2f ms, "
               "encode %.2f ms\n",
               simulate_ms_per_frame, medianOf(t.render_ms), medianOf(t.read_back_ms), medianOf(t.encode_ms));
}

void applyRenderOverrides(const RenderOptions& o, Scene& scene) {
  if (!o.size.empty()) setSize(scene, o.size);
  if (o.samples) {
    if (*o.samples != 1 && *o.samples != 2 && *o.samples != 4)
      throw Error(ExitCode::Usage, "--samples: MSAA takes 1, 2 or 4 samples (llvmpipe allows 4 at most)");
    scene.render.samples = *o.samples;
  }
  if (o.crf) scene.render.crf = *o.crf;
  if (o.shadow_map_size) scene.render.shadow_map_size = *o.shadow_map_size;
}

// Refuses to replace what exists unless asked (-y), before any work is done; with --skip-existing
// drops the frames whose PNG is already there (resuming an interrupted render), or every frame
// when the video exists.
void resolveExisting(const RenderOptions& o, const OutputTarget& target, std::vector<int>& frames) {
  if (o.skip_existing && o.overwrite) throw Error(ExitCode::Usage, "--skip-existing and --overwrite contradict each other");
  if (o.skip_existing && target.kind == OutputTarget::Kind::Video) {
    // A video only ever appears whole (VideoSink), so one that exists is a finished chunk.
    if (std::filesystem::exists(target.path)) frames.clear();
    return;
  }
  std::vector<std::filesystem::path> existing = existingOutputs(target, frames);
  for (const std::filesystem::path& p : existing) checkReplaceable(p);   // a folder or device: never
  if (existing.empty() || o.overwrite) return;
  if (o.skip_existing) {
    std::erase_if(frames, [&](int f) { return std::filesystem::exists(framePath(target, f)); });
    return;
  }
  std::string more = existing.size() > 1 ? " (and " + std::to_string(existing.size() - 1) + " more)" : "";
  throw Error(ExitCode::CantCreate, existing.front().string() + more +
                                        " already exists; add -y/--overwrite to replace it" +
                                        (target.kind == OutputTarget::Kind::PngSequence
                                             ? " or --skip-existing to keep it"
                                             : ""));
}

// Where a frame's diff image goes by default: next to its PNG, or beside a video as frame_####.
std::filesystem::path checkedFramePath(const OutputTarget& target, int frame) {
  if (target.kind == OutputTarget::Kind::PngSequence) return framePath(target, frame);
  std::filesystem::path folder = target.path.parent_path().empty() ? "." : target.path.parent_path();
  return framePath(parseOutput((folder / "").string(), 2), frame);
}

std::string formatSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f s", s);
  return buffer;
}

// `simulator` is null when the motion was read from a trajectory (`from`): there are no stage
// times or contact counts to report then, only where the motion came from.
nlohmann::json renderStats(const PhaseTimes& t, const Simulator* simulator, const std::string& from,
                           const SimulationPlan& plan, const Trajectory& trajectory, double wall, int rendered) {
  nlohmann::json stats = simulator ? simulationStats(*simulator, plan, trajectory.times.back())
                                   : nlohmann::json{{"motion_from_trajectory", from}};
  stats["command"] = "render";
  stats["wall_s"] = wall;
  stats["frames_rendered"] = rendered;
  stats["phases_s"] = {{"simulate", t.simulate}, {"render", t.render}, {"read_back", t.read_back}, {"encode", t.encode}};
  stats["per_frame_median_ms"] = {
      {"render", medianOf(t.render_ms)}, {"read_back", medianOf(t.read_back_ms)}, {"encode", medianOf(t.encode_ms)}};
  // Inside render: the overlays' share of it (PhaseTimes::overlays).
  stats["render_overlays_s"] = t.overlays;
  stats["per_frame_median_ms"]["render_overlays"] = medianOf(t.overlays_ms);
  return stats;
}

const char* modelName(ContactModel m) {
  switch (m) {
    case ContactModel::Baraff: return "baraff";
    case ContactModel::TimeStepping: return "time_stepping";
    case ContactModel::Penalty: return "penalty";
    case ContactModel::Auto: break;
  }
  return "auto";
}

int run(const RenderOptions& o) {
  const std::vector<ContactModel> compared = parseCompareModels(
      o.compare, {{"--from-trajectory", !o.from_trajectory.empty()}, {"--shard", !o.shard.shard.empty()},
                  {"--shards", o.shard.shards.has_value()}, {"--shards-env", !o.shard.shards_env.empty()},
                  {"--contact-model", !o.scene.contact_model.empty()}, {"--overlay", !o.overlays.empty()},
                  {"--check-against", !o.check_against.empty()}, {"--stats", !o.stats.empty()},
                  {"--dry-run", o.dry_run}});
  if (!o.check_against.empty() && !std::filesystem::is_directory(o.check_against)) {
    std::fprintf(stderr, "tumble: --check-against: %s is not a folder of frames\n", o.check_against.c_str());
    return static_cast<int>(CheckExit::BadInput);   // comparisons answer 2 for bad input, as diff does
  }
  Scene scene = loadSceneWithOverrides(o.scene);
  applyRenderOverrides(o, scene);
  if (!compared.empty()) prepareComparison(scene, compared);
  const CameraSpec& camera = pickCamera(scene, o.camera);
  OverlayRender overlays(scene, resolveOverlays(scene.overlays, o.overlays));
  overlays.checkMotionSource(!o.from_trajectory.empty());
  std::vector<int> frames = selectFrames(scene.render.frames, o.start, o.end, o.frames);
  std::optional<Shard> shard =   // a comparison renders whole: a job array's variables are not read
      compared.empty() ? chooseShard(o.shard, !o.frames.empty() || o.start || o.end, std::getenv) : std::nullopt;
  if (shard) frames = shardFrames(frames, *shard);
  std::string output = !o.output.empty() ? o.output : scene.output.value_or("out/" + scene.name + ".mp4");
  OutputTarget target = parseOutput(output, static_cast<int>(frames.size()));
  if (shard) useShardOutput(*shard, frames, target, o.scene.quiet);
  if (o.dry_run) {
    printDryRun({scene, camera, frames, target, o.overwrite}, stdout);
    return 0;
  }
  resolveExisting(o, target, frames);
  if (!o.stats.empty()) checkStatsOutput(o.stats, o.overwrite);
  // Of a sharded render, the last chunk writes the energy plot: it alone simulates the whole clip.
  if (!frames.empty() && (!shard || shard->index == shard->count)) overlays.checkOutputs(target, o.overwrite);
  if (frames.empty()) {
    if (!o.scene.quiet) std::fprintf(stderr, "tumble: every frame already exists; nothing to do\n");
    return 0;
  }
  SinkOptions sink_options{scene.render.width, scene.render.height, scene.render.fps,
                           scene.render.crf, o.overwrite, o.skip_existing,
                           frameProvenance(scene, o.camera + comparisonSettings(compared))};
  std::unique_ptr<FrameSink> sink = makeFrameSink(target, sink_options);
  if (!compared.empty())
    return renderComparison(compared, o.compare,
                            {scene, camera, frames, target, std::move(sink), o.shaders, o.scene.quiet,
                             o.scene.verbose, o.scene.keep_going});
  std::optional<CheckReport> check;
  if (!o.check_against.empty()) check.emplace(o.check.settings, false);

  BuiltWorld built = buildWorld(scene);
  for (const std::string& w : built.warnings)
    if (!o.scene.quiet) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());

  auto total_start = std::chrono::steady_clock::now();
  PhaseTimes times;
  // A fit camera frames the whole clip, so its motion is simulated to the end whatever is rendered.
  const int last_simulated = camera.form == CameraSpec::Form::Fit ? scene.render.frames : frames.back();
  SimulationPlan plan{built.step, scene.simulation.steps_per_frame, last_simulated, o.scene.keep_going};
  SceneDrawing drawing = prepareDrawing(scene, built.world);
  for (const std::string& w : drawing.warnings)
    if (!o.scene.quiet) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
  std::optional<Simulator> simulator;   // none when the motion is read from a trajectory file
  Trajectory trajectory;
  auto start = std::chrono::steady_clock::now();
  if (!o.from_trajectory.empty()) {
    std::vector<std::string> names;
    for (const RigidBody& b : built.world.bodies) names.push_back(b.name);
    trajectory = readTrajectoryFor(scene, names, o.from_trajectory, last_simulated);
  } else {
    simulator.emplace(std::move(built.world), plan);
    overlays.attach(*simulator, plan.step);
    Progress sim_progress("simulate", plan.frames, !o.scene.quiet);
    trajectory = simulator->run([&](int f) {
      overlays.onFrame(*simulator);
      sim_progress.update(f);
      stopIfInterrupted("simulating", f, plan.frames);
    });
    sim_progress.finish();
    reportFaults(simulator->faults());
    reportTarget(*simulator, o.scene.quiet);
  }
  times.simulate = secondsSince(start);
  overlays.prepare(simulator ? simulator->world() : built.world, drawing, trajectory,
                   modelName(simulator ? simulator->pipeline().runningModel(plan.step) : plan.step.model), plan.step.dt);

  RenderConfig config;
  config.width = scene.render.width;
  config.height = scene.render.height;
  config.samples = scene.render.samples;
  config.shadow_map_size = scene.render.shadow_map_size;
  config.shader_dir = o.shaders;
  std::unique_ptr<Renderer> renderer = Renderer::create(config);
  sink->setRenderer(renderer->glRenderer());
  std::vector<int> mesh_ids = uploadDrawing(*renderer, drawing);
  const std::vector<DrawCamera> cameras =
      cameraPath(camera, trajectory, bodyRadii(drawing), double(scene.render.width) / scene.render.height);

  Progress progress("render", static_cast<int>(frames.size()), !o.scene.quiet);
  RgbImage image;
  int done = 0;
  for (int frame : frames) {
    if (interruptRequested()) break;
    poseInstances(drawing, trajectory.frames[frame - 1], mesh_ids);
    drawing.frame.camera = cameras[frame - 1];
    start = std::chrono::steady_clock::now();
    overlays.addMarks(drawing.frame, frame, trajectory, scene.render.height);
    times.overlays_ms.push_back(1e3 * secondsSince(start));
    renderer->draw(drawing.frame);
    times.render_ms.push_back(1e3 * secondsSince(start));
    times.render += times.render_ms.back() / 1e3;
    start = std::chrono::steady_clock::now();
    renderer->readBack(image);
    times.read_back_ms.push_back(1e3 * secondsSince(start));
    times.read_back += times.read_back_ms.back() / 1e3;
    start = std::chrono::steady_clock::now();
    overlays.addText(image, frame, scene.render.frames, drawing.frame.camera);   // counted as rendering
    const double text_s = secondsSince(start);
    times.render_ms.back() += 1e3 * text_s;
    times.render += text_s;
    times.overlays_ms.back() += 1e3 * text_s;
    times.overlays += times.overlays_ms.back() / 1e3;
    start = std::chrono::steady_clock::now();
    sink->write(image, frame);
    times.encode_ms.push_back(1e3 * secondsSince(start));
    times.encode += times.encode_ms.back() / 1e3;
    if (check)   // in memory, so any output works, a video too
      checkAgainstGolden(*check, o.check_against, image, frame, checkedFramePath(target, frame), o.check.diff_out);
    progress.update(++done);
  }
  bool interrupted = done < static_cast<int>(frames.size());
  start = std::chrono::steady_clock::now();
  const std::string written = finishFrameSink(sink, target, interrupted);
  times.encode += secondsSince(start);
  progress.finish();
  if (!interrupted) overlays.writePlots(trajectory, o.overwrite, o.scene.quiet);
  double wall = secondsSince(total_start);

  if (!o.scene.quiet || interrupted) {
    double simulated = trajectory.times[frames.back() - 1];
    std::fprintf(stderr,
                 "tumble: %s %d of %zu frames (%.3f s simulated) to %s in %s: simulate %s, render %s, "
                 "read back %s, encode %s (%.1f frames/s)\n",
                 interrupted ? "interrupted after" : "rendered", done, frames.size(), simulated,
                 written.c_str(), formatSeconds(wall).c_str(), formatSeconds(times.simulate).c_str(),
                 formatSeconds(times.render).c_str(), formatSeconds(times.read_back).c_str(),
                 formatSeconds(times.encode).c_str(), done / std::max(wall, 1e-9));
  }
  if (o.scene.verbose) {
    printMedians(times, 1e3 * times.simulate / plan.frames);
    if (simulator) printPipelineStats(simulator->pipeline());
  }
  if (!o.stats.empty()) writeStatsFile(o.stats, o.overwrite, renderStats(times, simulator ? &*simulator : nullptr, o.from_trajectory, plan, trajectory, wall, done));
  if (interrupted) return static_cast<int>(ExitCode::Interrupted);
  if (!check) return 0;
  if (!o.scene.quiet || check->exitCode() != 0) check->printSummary("tumble render --check-against");
  return check->exitCode();
}

}  // namespace

std::function<int()> addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Simulate a scene and render it to a video or PNG sequence");
  addSceneOptions(*cmd, o->scene);
  addKeepGoingOption(*cmd, o->scene);
  cmd->add_option("-o,--output", o->output,
                  "out.mp4 | out.mkv | out.mov | out/ | 'out/frame_####.png' | 'out/frame_%04d.png' "
                  "(default: the scene's \"output\", else out/SCENE.mp4)");
  cmd->add_option("--camera", o->camera, "Render through the scene's camera of this name (its \"cameras\")");
  cmd->add_option("--size", o->size, "Frame size WIDTHxHEIGHT, e.g. 1280x720");
  cmd->add_option("-s,--start", o->start, "First frame to render (frames count from 1)");
  cmd->add_option("-e,--end", o->end, "Last frame to render");
  cmd->add_option("--frames", o->frames, "Frames to render, e.g. 1,5,10..20");
  cmd->add_option("--crf", o->crf, "H.264 quality, 0 (lossless) .. 51 (worst); default 23")
      ->check(CLI::Range(0, 51));
  cmd->add_option("--samples", o->samples, "MSAA samples: 1, 2 or 4");
  cmd->add_option("--shadow-map-size", o->shadow_map_size, "Shadow map texels per side")
      ->check(CLI::Range(256, 8192));
  cmd->add_option("--shaders", o->shaders,
                  "Read the GLSL from this folder (e.g. the source tree's shaders/) instead of the copy "
                  "built into tumble, to try shader edits without rebuilding")
      ->envname("TUMBLE_SHADER_DIR");
  cmd->add_option("--stats", o->stats,
                  "Write where the time went (phases, pipeline stages), step and contact counts, energy drift "
                  "and deepest penetration as JSON to this file")
      ->type_name("FILE.json");
  cmd->add_flag("-y,--overwrite", o->overwrite, "Replace existing outputs");
  cmd->add_flag("--dry-run", o->dry_run,
                "Print the resolved settings, each frame's simulated time and output file; write nothing");
  cmd->add_flag("--skip-existing", o->skip_existing,
                "Keep PNG frames that already exist (resume); with a video, do nothing if it exists (a finished chunk)");
  cmd->add_option("--check-against", o->check_against,
                  "Compare each frame with DIR/frame_####.png; exit 0 pass, 1 fail, 2 missing or other size");
  addCheckOptions(*cmd, o->check);
  addScaleOutOptions(*cmd, o->from_trajectory, o->shard);
  addOverlayOption(*cmd, o->overlays);
  addCompareOptions(*cmd, o->compare);
  return [o] { return run(*o); };
}

}  // namespace tumble
