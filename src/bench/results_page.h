// The results as a markdown page (docs/bench/results.md): the run's stamp, the headline error and
// cost of every setting per dt, the piles side by side, then each scene's full table under its
// plot, the same tables tumble-bench prints. Written by the run that measured the figures, never
// by hand.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "bench/report.h"
#include "bench/run_stamp.h"

namespace tumble::bench {

struct PageProgress {
  std::size_t scenes_planned = 0;   // the page is rewritten after each scene: partial until all ran
  double elapsed_s = 0;             // wall s since the run started
};

void writeResultsPage(std::ostream& out, const RunStamp& stamp, const PageProgress& progress,
                      const std::vector<SceneResults>& all);
void writeResultsPage(const std::filesystem::path& file, const RunStamp& stamp,
                      const PageProgress& progress, const std::vector<SceneResults>& all);

}  // namespace tumble::bench
