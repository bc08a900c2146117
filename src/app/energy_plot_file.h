// The energy_plot overlay's files: NAME.energy.png and NAME.energy.svg beside the render's output
// (a video's name without its extension; a PNG sequence's folder and the scene's name).
#pragma once

#include <filesystem>
#include <string>

#include "io/output_path.h"
#include "plot/energy_plot.h"

namespace tumble {

// The PNG's path; the SVG's is the same with ".svg".
std::filesystem::path energyPlotPath(const OutputTarget& target, const std::string& scene_name);
// Before any work: an existing plot is refused (Error(CantCreate), 73) unless `overwrite`, and a
// name taken by a folder or a device always.
void checkEnergyPlotOutputs(const std::filesystem::path& png, bool overwrite);
// Both files, each written whole or not at all.
void writeEnergyPlot(const std::filesystem::path& png, const plot::EnergySeries& series, bool overwrite);

}  // namespace tumble
