// The overlays' text, drawn with cairo (plot/canvas.h) on a transparent layer the size of the frame:
// the HUD in the top-left corner, and the legend of the marks (their colours and scales) in the
// bottom-left one. Each sits on a translucent dark panel, so it reads on any background.
#pragma once

#include <string>

#include "app/overlay_marks.h"
#include "plot/canvas.h"
#include "scene/overlay_spec.h"

namespace tumble {

struct HudFigures {
  double time_s = 0;
  int frame = 1, frames = 1;
  std::string model;               // the contact model that runs ("baraff", ...)
  double dt_s = 0;
  double kinetic = 0, potential = 0, start_total = 0;   // J
  int contacts = 0;
  double deepest_m = 0;
};

// Text size for a frame this tall (px): 18 px text at 720 rows, never under 8.
double overlayFontPx(int frame_height);
void drawHud(plot::Canvas& layer, const HudFigures& hud, int frame_height);
// What the marks of `spec` mean, with the clip's scales; nothing when no marks are drawn.
void drawMarksLegend(plot::Canvas& layer, const OverlaySpec& spec, const OverlayScales& scales, int frame_height);

}  // namespace tumble
