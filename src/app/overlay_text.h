// The overlays' text, drawn with cairo (plot/canvas.h) on transparent layers to lay over the frame:
// the HUD in the top-left corner, and the legend of the marks (their colours and scales) in the
// bottom-left one. Each sits on a translucent dark panel, so it reads on any background, and each
// layer is only the panel's size, so laying it over a 1280x720 frame touches only its pixels.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/overlay_marks.h"
#include "base/image.h"
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

// A panel's pixels (RGBA, premultiplied: plot::Canvas::layer) and where its top-left corner goes.
struct OverlayPanel {
  RgbaImage layer;
  int x = 0, y = 0;   // px, in the frame
};

// Text size for a frame this tall (px): 18 px text at 720 rows, never under 8.
double overlayFontPx(int frame_height);
OverlayPanel hudPanel(const HudFigures& hud, int frame_height);
// One line of text on the same panel, beside the point (x, y) px in the frame: up and to its right
// (the back_step overlay's count of trials, by its impact).
OverlayPanel labelPanel(const std::string& text, double font_px, double x, double y);
// Lines of text on the same panel, `font_px` tall, in the top-left corner of a picture this tall
// (or the bottom-left one, `from_bottom`): the tiles' labels of render --compare-models.
OverlayPanel textPanel(const std::vector<std::string>& lines, double font_px, int frame_height, bool from_bottom);
// What the marks of `spec` mean, with the clip's scales; none when no marks are drawn.
std::optional<OverlayPanel> legendPanel(const OverlaySpec& spec, const OverlayScales& scales, int frame_height);

}  // namespace tumble
