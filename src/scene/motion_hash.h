// A fingerprint of everything in a scene that shapes its motion, so a trajectory written from one
// scene can be told apart from another's before frames are rendered from it.
#pragma once

#include <string>

#include "scene/scene.h"

namespace tumble {

// 16 hex digits (FNV-1a, 64 bits) over: the scene's JSON as read, after --set and --patch (comments
// and layout do not count, key order does not count) without what only changes the picture ("camera", "cameras",
// "lights", "output", "overlays", "overlay_bodies", "render", and each body's colour and "draw"); the resolved timing and model, command-line
// overrides included (fps, dt, steps per frame — which --time-scale changes —, integrator, contact model, sleeping); and the bytes
// of every mesh file the bodies read. The frame count is left out: a longer run has the same
// first frames. Throws Error(MissingInput) if the scene file cannot be read again.
std::string motionHash(const Scene& scene);

}  // namespace tumble
