// Command-line overrides of scene settings (--fps, --duration, --dt, ...). They go through the
// same checks as the file, so an override can never make a scene the loader would refuse.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace tumble {

// The frames of a clip of `duration_s` at `fps`: frame k shows the instant (k - 1) / fps, so the
// clip takes round(duration_s * fps) + 1 frames, the first at t = 0 and the last at the duration
// (a 2 s clip at 30 fps: 61 frames, t = 0 .. 2 s).
int framesForDuration(double duration_s, int fps);
// The time the last of `frames` frames shows: (frames - 1) / fps.
double durationOfFrames(int frames, int fps);

// Chooses the whole number of steps per frame closest to interval / dt and makes dt divide the
// frame interval exactly. Throws Error(Usage) when `dt_s` is not within 0.1 % of such a step.
void setTimeStep(Scene& scene, double dt_s, const std::string& flag);
// A new frame rate keeps the step (dt) as close as the new frame interval allows.
void setFrameRate(Scene& scene, int fps);
void setDuration(Scene& scene, double duration_s);
void setFrameCount(Scene& scene, int frames);
// Another contact model. Throws Error(Usage) when the scene asks for Poisson's or Stronge's
// restitution law and the model is not "baraff" (the only one with a choice), as the loader does.
void setContactModel(Scene& scene, ContactModel model, const std::string& flag);
// "1280x720" -> width and height. Throws Error(Usage) on anything else.
void setSize(Scene& scene, const std::string& size);

}  // namespace tumble
