#include "scene/scene_overrides.h"

#include <cmath>
#include <cstdio>
#include <regex>

#include "base/error.h"

namespace tumble {
namespace {

[[noreturn]] void usage(const std::string& message) { throw Error(ExitCode::Usage, message); }

std::string formatScale(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

// The loader's bound on a whole run (scene_loader.cpp), checked again after a flag changed it.
void checkTotalSteps(const Scene& scene, const std::string& flag) {
  if (scene.render.frames > 1000000)
    usage(flag + ": " + std::to_string(scene.render.frames) + " frames; at most 1000000");
  double steps = double(scene.render.frames) * scene.simulation.steps_per_frame;
  if (steps > 1e8)
    usage(flag + ": " + std::to_string(scene.render.frames) + " frames of " +
          std::to_string(scene.simulation.steps_per_frame) +
          " steps each are more than 100000000 steps; use a larger step or fewer frames");
}

}  // namespace

void setTimeStep(Scene& scene, double dt_s, const std::string& flag) {
  if (!(dt_s > 0 && dt_s <= 0.1)) usage(flag + ": the step must be in (0, 0.1] s");
  double interval = 1.0 / scene.render.fps;
  long whole = std::lround(interval / dt_s);
  if (whole < 1 || std::abs(interval / dt_s - whole) > 1e-3 * whole)
    usage(flag + ": " + std::to_string(dt_s) + " s does not divide the frame interval 1/" +
          std::to_string(scene.render.fps) + " s; try 1/" +
          std::to_string(std::max(1L, whole) * scene.render.fps));
  if (whole > 100000) usage(flag + ": more than 100000 steps per frame");
  scene.simulation.steps_per_frame = static_cast<int>(whole);
  scene.simulation.step.dt = interval / whole;
  checkTotalSteps(scene, flag);
}

void setContactModel(Scene& scene, ContactModel model, const std::string& flag) {
  const RestitutionLaw law = scene.simulation.step.contact.restitution_law;
  if (model != ContactModel::Baraff && model != ContactModel::Auto && law != RestitutionLaw::Newton)
    usage(flag + ": only the baraff contact model has a choice of restitution law, and the scene asks for " +
          (law == RestitutionLaw::Poisson ? "\"poisson\"" : "\"stronge\"") + " (simulation.restitution_law)");
  if (model == ContactModel::Penalty && !scene.joints.empty())
    usage(flag + ": the penalty contact model does not simulate joints, and the scene has " +
          std::to_string(scene.joints.size()) + " (\"joints\")");
  scene.simulation.step.model = model;
}

int framesForDuration(double duration_s, int fps) {
  return std::max(1, static_cast<int>(std::lround(duration_s * fps)) + 1);
}

double durationOfFrames(int frames, int fps) { return (frames - 1) / double(fps); }

void setFrameRate(Scene& scene, int fps) {
  if (fps < 1 || fps > 1000) usage("--fps: " + std::to_string(fps) + " is outside [1, 1000]");
  double duration = durationOfFrames(scene.render.frames, scene.render.fps);
  double dt = scene.simulation.step.dt;
  scene.render.fps = fps;
  scene.render.frames = framesForDuration(duration, fps);
  long whole = std::max(1L, std::lround(1.0 / fps / dt));
  scene.simulation.steps_per_frame = static_cast<int>(whole);
  scene.simulation.step.dt = 1.0 / fps / whole;
  checkTotalSteps(scene, "--fps");
}

void setDuration(Scene& scene, double duration_s) {
  if (!(duration_s > 0) || duration_s * scene.render.fps > 1e6)
    usage("--duration: must be positive and at most 1000000 frames long");
  scene.render.frames = framesForDuration(duration_s, scene.render.fps);
  checkTotalSteps(scene, "--duration");
}

void setFrameCount(Scene& scene, int frames) {
  if (frames < 1 || frames > 1000000) usage("--frame-count: must be in [1, 1000000]");
  scene.render.frames = frames;
  checkTotalSteps(scene, "--frame-count");
}

void setTimeScale(Scene& scene, double scale) {
  if (!(scale > 0 && scale <= 100)) usage("--time-scale: must be in (0, 100], e.g. 0.25 for four times slower");
  const int steps = scene.simulation.steps_per_frame;
  const double wanted = steps * scale;   // steps between the new frames
  const long whole = std::lround(wanted);
  // The same tolerance as --dt: a scale written as a rounded decimal (0.333333) still lands.
  if (whole < 1 || std::abs(wanted - whole) > 1e-3 * whole) {
    char dt[32];
    std::snprintf(dt, sizeof dt, "%.6g", scene.simulation.step.dt);
    usage("--time-scale " + formatScale(scale) + ": a frame would be " + formatScale(wanted) + " steps of " + dt +
          " s; the step must divide the frame interval. Use a scale that is a multiple of 1/" + std::to_string(steps) +
          ", or a smaller step (--dt)");
  }
  const double span = double(scene.render.frames - 1) * steps;   // steps from the first frame to the last
  scene.simulation.steps_per_frame = static_cast<int>(whole);
  scene.render.frames = static_cast<int>(std::lround(span / whole)) + 1;
  scene.render.time_scale = double(whole) / steps;
  checkTotalSteps(scene, "--time-scale");
}

void setSize(Scene& scene, const std::string& size) {
  std::smatch m;
  static const std::regex form(R"((\d{1,5})x(\d{1,5}))");
  if (!std::regex_match(size, m, form)) usage("--size: expected WIDTHxHEIGHT, e.g. 1280x720, got \"" + size + "\"");
  int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 16 || h < 16 || w > 8192 || h > 8192) usage("--size: each side must be in [16, 8192]");
  scene.render.width = w;
  scene.render.height = h;
}

}  // namespace tumble
