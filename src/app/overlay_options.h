// render --overlay NAMES: the overlays to draw, beside the scene's "overlays".
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scene/overlay_spec.h"

namespace tumble {

// --overlay contacts,forces,hud (repeatable; "all" for every kind).
void addOverlayOption(CLI::App& command, std::vector<std::string>& names);
// The scene's overlays, then the command line's. An unknown name is a bad command line
// (Error(Usage), 64), with "did you mean".
OverlaySpec resolveOverlays(const OverlaySpec& scene, const std::vector<std::string>& names);

}  // namespace tumble
