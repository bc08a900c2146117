#include "app/energy_inset_panel.h"

#include <algorithm>
#include <cmath>

#include "plot/canvas.h"
#include "plot/energy_inset.h"

namespace tumble {

OverlayPanel energyInsetPanel(const plot::EnergySeries& series, std::size_t upto, int frame_width, int frame_height) {
  const double font_px = overlayFontPx(frame_height);
  const int width = static_cast<int>(std::max(std::round(0.3 * frame_width), 10 * font_px));
  const int height = static_cast<int>(std::max(std::round(0.45 * width), 5 * font_px));
  plot::Canvas c(plot::Canvas::Target::Layer, width, height);
  plot::drawEnergyInset(c, width, height, font_px, series, upto);
  const int margin = static_cast<int>(std::round(font_px * 0.4));   // as the HUD's (overlay_text.cpp)
  return {c.layer(), frame_width - margin - width, margin};
}

}  // namespace tumble
