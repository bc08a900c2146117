#include "app/energy_plot_file.h"

#include "base/error.h"
#include "io/atomic_file.h"
#include "io/png_file.h"

namespace tumble {
namespace {

std::filesystem::path svgOf(std::filesystem::path png) { return png.replace_extension(".svg"); }

}  // namespace

std::filesystem::path energyPlotPath(const OutputTarget& target, const std::string& scene_name) {
  if (target.kind == OutputTarget::Kind::Video) {
    std::filesystem::path p = target.path;
    return p.replace_extension(".energy.png");
  }
  const std::filesystem::path folder = target.path.parent_path();
  return folder / (scene_name + ".energy.png");
}

void checkEnergyPlotOutputs(const std::filesystem::path& png, bool overwrite) {
  for (const std::filesystem::path& p : {png, svgOf(png)}) {
    if (!std::filesystem::exists(p)) continue;
    checkReplaceable(p);
    if (!overwrite)
      throw Error(ExitCode::CantCreate, p.string() + " already exists; add -y/--overwrite to replace it");
  }
}

void writeEnergyPlot(const std::filesystem::path& png, const plot::EnergySeries& series, bool overwrite) {
  if (!png.parent_path().empty()) std::filesystem::create_directories(png.parent_path());
  plot::Canvas raster(plot::Canvas::Target::Raster, plot::kEnergyPlotWidth, plot::kEnergyPlotHeight);
  plot::drawEnergyPlot(raster, series);
  writePng(png, raster.image(), overwrite);
  plot::Canvas vector(plot::Canvas::Target::Svg, plot::kEnergyPlotWidth, plot::kEnergyPlotHeight);
  plot::drawEnergyPlot(vector, series);
  writeFileWhole(svgOf(png), vector.finishSvg(series.title), overwrite);
}

}  // namespace tumble
