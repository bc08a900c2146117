// A small energy plot to lay over a frame's corner (the energy_inset overlay): kinetic, potential
// and total energy against time, drawn up to the frame shown. Its axes span the whole clip, fixed
// from frame to frame, so the lines grow from the left as the clip plays and a drift reads as a
// slope. Light lines on a translucent dark panel, as the rest of the text over frames; no tick
// labels at this size: the top line gives the total now and the range the panel spans.
#pragma once

#include <cstddef>

#include "plot/canvas.h"
#include "plot/energy_plot.h"

namespace tumble::plot {

// Draws on a Layer canvas of width x height px; `upto`: how many samples of `series` to draw (the
// frames up to the one shown); `font_px`: the text's height.
void drawEnergyInset(Canvas& canvas, double width, double height, double font_px, const EnergySeries& series,
                     std::size_t upto);

}  // namespace tumble::plot
