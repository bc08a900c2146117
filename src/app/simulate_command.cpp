// tumble simulate SCENE [--trajectory FILE.csv] [--every-step]
#include <cstdio>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/gltf_export.h"
#include "app/pipeline_stats.h"
#include "app/progress.h"
#include "app/scene_options.h"
#include "app/stats_file.h"
#include "app/trajectory_source.h"
#include "base/error.h"
#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "io/trajectory_csv.h"

namespace tumble {
namespace {

struct SimulateOptions {
  SceneOptions scene;
  std::string trajectory;
  std::string stats;   // --stats FILE.json; empty: none
  std::string gltf;    // --gltf FILE.glb; empty: none
  bool every_step = false, overwrite = false;
};

void writeRows(CsvTrajectoryWriter& csv, double time, const std::vector<std::string>& names,
               const std::vector<BodySample>& samples) {
  double v[CsvTrajectoryWriter::kValues];
  for (std::size_t b = 0; b < samples.size(); ++b) {
    const BodySample& s = samples[b];
    const double values[] = {s.x.x(), s.x.y(), s.x.z(), s.q.w(), s.q.x(), s.q.y(), s.q.z(),
                             s.v.x(), s.v.y(), s.v.z(), s.w.x(), s.w.y(), s.w.z()};
    std::copy(std::begin(values), std::end(values), v);
    csv.row(time, names[b], v);
  }
}

std::vector<BodySample> samplesOf(const World& world) {
  std::vector<BodySample> out;
  out.reserve(world.bodies.size());
  for (const RigidBody& b : world.bodies) out.push_back(sampleOf(b));
  return out;
}

int run(const SimulateOptions& o) {
  Scene scene = loadSceneWithOverrides(o.scene);
  if (!o.stats.empty()) checkStatsOutput(o.stats, o.overwrite);
  if (!o.gltf.empty()) checkGltfOutput(o.gltf, o.overwrite);
  std::unique_ptr<CsvTrajectoryWriter> csv;
  if (!o.trajectory.empty())
    csv = std::make_unique<CsvTrajectoryWriter>(o.trajectory, o.overwrite,
                                                std::vector<std::string>{trajectoryComment(scene, o.every_step)});
  BuiltWorld built = buildWorld(scene);
  for (const std::string& w : built.warnings)
    if (!o.scene.quiet) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
  std::vector<std::string> names;
  for (const RigidBody& b : built.world.bodies) names.push_back(b.name);

  SimulationPlan plan{built.step, scene.simulation.steps_per_frame, scene.render.frames, o.scene.keep_going};
  std::optional<SceneDrawing> drawing;   // the visual meshes, for --gltf
  if (!o.gltf.empty()) drawing = prepareDrawing(scene, built.world);
  Simulator simulator(std::move(built.world), plan);
  Progress progress("simulate", plan.frames, !o.scene.quiet);
  auto start = std::chrono::steady_clock::now();
  auto on_step = [&](const World& w) { writeRows(*csv, w.time, names, samplesOf(w)); };
  if (csv && o.every_step) writeRows(*csv, 0, names, samplesOf(simulator.world()));
  Trajectory trajectory = simulator.run(
      [&](int f) {
        progress.update(f);
        stopIfInterrupted("simulating", f, plan.frames);
      },
      csv && o.every_step ? std::function<void(const World&)>(on_step) : nullptr);
  progress.finish();
  double wall = secondsSince(start);
  reportFaults(simulator.faults());
  reportTarget(simulator, o.scene.quiet);
  if (csv && !o.every_step)
    for (std::size_t k = 0; k < trajectory.frames.size(); ++k)
      writeRows(*csv, trajectory.times[k], names, trajectory.frames[k]);
  if (csv) csv->close();
  if (drawing) writeGltf(o.gltf, o.overwrite, *drawing, trajectory);
  if (!o.scene.quiet) {
    long steps = static_cast<long>(plan.frames - 1) * plan.steps_per_frame;
    double simulated = trajectory.times.back();
    std::fprintf(stderr, "tumble: simulated %.3f s (%ld steps of %.6g s, %zu bodies) in %.3f s (%.3g s per simulated s)%s%s\n",
                 simulated, steps, plan.step.dt, names.size(), wall,
                 simulated > 0 ? wall / simulated : 0.0, csv ? "; trajectory in " : "",
                 !csv ? "" : o.trajectory == "-" ? "standard output" : o.trajectory.c_str());
  }
  if (o.scene.verbose) printPipelineStats(simulator.pipeline());
  if (!o.stats.empty()) {
    nlohmann::json stats = simulationStats(simulator, plan, trajectory.times.back());
    stats["command"] = "simulate";
    stats["wall_s"] = wall;
    writeStatsFile(o.stats, o.overwrite, stats);
  }
  return 0;
}

}  // namespace

std::function<int()> addSimulateCommand(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate a scene without rendering; write its motion as CSV");
  addSceneOptions(*cmd, o->scene);
  addKeepGoingOption(*cmd, o->scene);
  cmd->add_option("--trajectory", o->trajectory,
                  "CSV file ('-': standard output): time,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz (world frame, centre of mass, SI), "
                  "after a '# tumble trajectory' line with the scene's motion hash; render --from-trajectory reads it");
  cmd->add_flag("--every-step", o->every_step, "One row per body per step instead of per frame");
  cmd->add_option("--stats", o->stats,
                  "Write where the time went, step and contact counts, energy drift and deepest penetration "
                  "as JSON to this file")
      ->type_name("FILE.json");
  cmd->add_option("--gltf", o->gltf,
                  "Write the motion as an animated glTF 2.0 binary (.glb): a node per body with its visual mesh "
                  "and colour, a key per frame (for Blender)")
      ->type_name("FILE.glb");
  cmd->add_flag("-y,--overwrite", o->overwrite, "Replace an existing trajectory, stats or glTF file");
  return [o] { return run(*o); };
}

}  // namespace tumble
