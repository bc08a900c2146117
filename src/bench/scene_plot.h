// The speed-against-error chart of one scene: x = wall s per simulated s, y = the scene's headline
// error, both on log axes with decade and minor ticks; one line per engine setting through its dt
// values, coloured by family (series_style.h), and a legend naming each setting.
#pragma once

#include <string>
#include <vector>

#include "bench/run_point.h"
#include "bench/series_style.h"
#include "plot/canvas.h"

namespace tumble::bench {

using plot::Align;
using plot::Canvas;
using plot::Font;

constexpr int kPlotWidth = 960, kPlotHeight = 600;   // px, of the PNG and of the SVG

struct PlotLabels {
  std::string title;     // "S1 cube drop"
  std::string metric;    // the metric plotted, "apex_err"
  std::string y_title;   // "apex_err = |apex − 0.75 m| (m)"
};

// Draws on a kPlotWidth x kPlotHeight canvas. `results` are the rows of one scene. Values <= 0
// (exact answers) sit on a dashed "0" line under the lowest decade; failed and non-finite points
// are left out.
void drawScenePlot(Canvas& canvas, const PlotLabels& labels, const std::vector<RunResult>& results);

// The value of `name` in a result's metrics, NaN when absent.
double metricValue(const RunResult& r, const std::string& name);

}  // namespace tumble::bench
