// Reads back the CSV that writeCsv (report.h) writes, so that plots can be redrawn from a run's
// figures without running anything again (tumble-bench --plot-from).
#pragma once

#include <filesystem>
#include <istream>
#include <vector>

#include "bench/report.h"

namespace tumble::bench {

// Scenes in the order of their first row, each RunResult with its metrics in file order; a scene's
// dts are those of its rows. Throws std::runtime_error naming the file and line on a malformed
// row or an unknown scene id.
std::vector<SceneResults> readResultsCsv(std::istream& in, const std::string& name);
std::vector<SceneResults> readResultsCsv(const std::filesystem::path& file);

}  // namespace tumble::bench
