#include "app/pipeline_stats.h"

#include <cstdio>

namespace tumble {

void printPipelineStats(const Pipeline& pipeline) {
  double total = 0;
  for (const StageTime& s : pipeline.profile()) total += s.seconds;
  for (const StageTime& s : pipeline.profile())
    if (s.seconds > 0)
      std::fprintf(stderr, "  stage %-10s %9.4f s  %5.1f %%\n", s.name.c_str(), s.seconds,
                   total > 0 ? 100 * s.seconds / total : 0.0);
  const PipelineCounters& c = pipeline.counters();
  std::fprintf(stderr,
               "  sub-steps %ld, back-steps %ld (%ld evaluations), projections %ld, unresolved %ld; "
               "contacts: colliding %d, resting %d, LCP pivots %d, LCP failures %d\n",
               c.substeps, c.back_steps, c.bisection_evaluations, c.projections, c.stuck_substeps,
               c.contacts.colliding, c.contacts.resting, c.contacts.pivots, c.contacts.failures);
}

}  // namespace tumble
