// How each engine setting looks on a plot. The colour says the family, so that a reader sees at a
// glance which contact method a line belongs to: tumble's auto black, its Baraff settings reds,
// time stepping oranges, penalty teals, each peer engine a hue of its own. Within a family the
// shade and the marker tell the settings apart.
#pragma once

#include <string>

#include "plot/canvas.h"

namespace tumble::bench {

using plot::Rgb;
using plot::Marker;

enum class Family { TumbleAuto, TumbleBaraff, TumbleTimeStepping, TumblePenalty, Bullet, Ode, Mujoco, Other };

struct SeriesStyle {
  Rgb colour;
  Marker marker;
  // px. tumble-auto, the default, is drawn broader than the rest: where a setting coincides with
  // it (auto picks the Baraff model on most scenes) that line shows on a black outline.
  double line_width = 1.6;
};

// From the setting's name (tumble's settings are named by model: tumble-ts*, tumble-penalty-*,
// tumble-auto; every other tumble-* setting is the Baraff model) or, for a peer, its engine.
Family familyOf(const std::string& setting, const std::string& engine);
// The style of the `index`-th setting (0, 1, ...) of `family` in a plot.
SeriesStyle seriesStyle(Family family, int index);

}  // namespace tumble::bench
