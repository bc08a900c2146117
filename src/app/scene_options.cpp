#include "app/scene_options.h"

#include <cstdio>

#include "base/error.h"
#include "dynamics/parallel_for.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

namespace tumble {

void addSceneOptions(CLI::App& command, SceneOptions& o) {
  command.add_option("scene", o.scene, "Scene file (JSON, schema version 1)")->required();
  command.add_option("--patch", o.patches,
                     "Merge this JSON patch (RFC 7386) into the scene before reading it; its \"bodies\" may be "
                     "an object keyed by body name. Repeatable; applied in order, before any --set")
      ->type_name("FILE.json")
      ->allow_extra_args(false);   // one value per flag, so "--patch p.json scene.json" keeps its scene
  command.add_option("--set", o.sets,
                     "Set a scene value before reading it, e.g. bodies.ball.restitution=0.9, render.draw=hulls, "
                     "lights.0.intensity=2 (list entries by name or index; the value is JSON, else a string). "
                     "Repeatable")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  command.add_option("--fps", o.fps, "Frames per second (overrides render.fps)");
  command.add_option("--duration", o.duration_s, "Seconds to simulate (overrides render.duration_s)");
  command.add_option("--time-scale", o.time_scale,
                     "Slow motion: S simulated seconds per second of the clip (0.25: four times the frames per "
                     "simulated second, each at its own instant); the step must divide the new frame interval. "
                     "Give the same scale to simulate --trajectory and render --from-trajectory");
  command.add_option("--dt", o.dt_s, "Simulation step in s; must divide 1/fps (overrides simulation.step.dt)");
  command.add_option("--integrator", o.integrator, "rk4 | semi_implicit_euler (overrides simulation.step.integrator)")
      ->check(CLI::IsMember({"rk4", "semi_implicit_euler"}));
  command.add_option("--contact-model", o.contact_model,
                     "auto | baraff | time_stepping | penalty (overrides simulation.contact_model; penalty takes the "
                     "scene's \"penalty\" settings or their defaults)")
      ->check(CLI::IsMember({"auto", "baraff", "time_stepping", "penalty"}));
  command.add_flag("--no-sleep", o.no_sleep,
                   "Never freeze bodies at rest: every body is simulated to the end (overrides simulation.step.sleep.enabled)");
  command.add_option("--threads", o.threads,
                     "Threads for the simulation's detection and contact solve; 0: every hardware thread. The "
                     "motion is bit-identical at any count (default 1)")
      ->check(CLI::NonNegativeNumber);
  command.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
  command.add_flag("-v,--verbose", o.verbose, "Print warnings in full and where the time went");
}

void addKeepGoingOption(CLI::App& command, SceneOptions& o) {
  command.add_flag("--keep-going", o.keep_going,
                   "On a numerical fault (NaN, runaway or gained energy, deep penetration, a teleport) "
                   "report it and go on instead of stopping with exit code 70");
}

void reportFaults(const FaultCheck& faults) {
  // Printed even with -q: the output may be garbage from the first fault on.
  if (faults.total() > 0) std::fprintf(stderr, "tumble: warning: %s\n", faults.summary().c_str());
}

void reportTarget(const Simulator& simulator, bool quiet) {
  if (!simulator.target()) return;
  const TargetWatch& watch = *simulator.target();
  for (const TargetWatch::Line& line : watch.report()) {
    if (!line.met)
      std::fprintf(stderr, "tumble: warning: accuracy target missed: %s\n", line.text.c_str());
    else if (!quiet)
      std::fprintf(stderr, "tumble: target: %s\n", line.text.c_str());
  }
}

Scene loadSceneWithOverrides(const SceneOptions& o) {
  std::vector<SceneEdit> edits;
  for (const std::string& p : o.patches) edits.push_back({SceneEdit::Kind::Patch, p});
  for (const std::string& s : o.sets) edits.push_back({SceneEdit::Kind::Set, s});
  Scene scene = loadScene(o.scene, edits);
  if (o.fps) setFrameRate(scene, *o.fps);
  if (o.duration_s) setDuration(scene, *o.duration_s);
  if (o.dt_s) setTimeStep(scene, *o.dt_s, "--dt");
  if (!o.integrator.empty())
    scene.simulation.step.integrator = o.integrator == "rk4" ? Integrator::Rk4 : Integrator::SemiImplicitEuler;
  if (!o.contact_model.empty())
    setContactModel(scene,
                    o.contact_model == "baraff"          ? ContactModel::Baraff
                    : o.contact_model == "penalty"       ? ContactModel::Penalty
                    : o.contact_model == "time_stepping" ? ContactModel::TimeStepping
                                                         : ContactModel::Auto,
                    "--contact-model");
  if (o.no_sleep) scene.simulation.step.sleep.enabled = false;
  scene.simulation.step.threads = resolveThreads(o.threads);
  if (o.time_scale) setTimeScale(scene, *o.time_scale);   // last: it divides the step the flags above set
  return scene;
}

}  // namespace tumble
