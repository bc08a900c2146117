// The speed-against-error chart of one scene: x = wall s per simulated s, y = the scene's headline
// error, both log scale; one line per engine setting through its dt values.
#pragma once

#include <string>
#include <vector>

#include "base/image.h"
#include "bench/run_point.h"

namespace tumble::bench {

// `results` are the rows of one scene. Values <= 0 (exact answers) sit on a "0" line under the
// lowest decade; failed and non-finite points are left out.
RgbImage plotScene(const std::string& title, const std::string& metric,
                   const std::vector<RunResult>& results);

// The value of `name` in a result's metrics, NaN when absent.
double metricValue(const RunResult& r, const std::string& name);

}  // namespace tumble::bench
