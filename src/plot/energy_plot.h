// The energy plot of a run: kinetic, potential and total energy against time on linear axes, with
// a legend, written beside a render as NAME.energy.png and NAME.energy.svg (the energy_plot
// overlay). Plain data in, so the plot knows nothing of the simulation.
#pragma once

#include <string>
#include <vector>

#include "plot/canvas.h"

namespace tumble::plot {

constexpr int kEnergyPlotWidth = 960, kEnergyPlotHeight = 540;   // px, of the PNG and of the SVG

struct EnergySeries {
  std::string title;                         // "knockdown: energy (baraff)"
  std::vector<double> time;                  // s, ascending
  std::vector<double> kinetic, potential;    // J, one per time; the total is their sum
};

// Draws on a kEnergyPlotWidth x kEnergyPlotHeight canvas.
void drawEnergyPlot(Canvas& canvas, const EnergySeries& series);

}  // namespace tumble::plot
