// Where and how large the energy_inset overlay's plot (plot/energy_inset.h) sits in a frame: the
// top-right corner, the HUD taking the top-left and the legend the bottom-left; about 30 % of the
// frame's width, never narrower than ten characters, so its lines stay apart at 160x120.
#pragma once

#include <cstddef>

#include "app/overlay_text.h"
#include "plot/energy_plot.h"

namespace tumble {

// The clip's energies, drawn up to sample `upto` (the frames shown so far).
OverlayPanel energyInsetPanel(const plot::EnergySeries& series, std::size_t upto, int frame_width, int frame_height);

}  // namespace tumble
