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
               "  sub-steps %ld, back-steps %ld (%ld evaluations), projections %ld (%ld past a body's reach, "
               "not made), unresolved %ld, impacts too deep to go back for %ld, contact work taken back %ld, "
               "steps solved again for a body sent past its reach %ld, steps taken again in halves for a body "
               "moved farther than its speeds explain %ld\n",
               c.substeps, c.back_steps, c.bisection_evaluations, c.projections, c.capped_projections,
               c.stuck_substeps, c.inconsistent_pairs, c.contact_work_paid, c.resolved_for_outrun, c.split_steps);
  std::fprintf(stderr,
               "  contacts: colliding %ld, resting %ld, LCP pivots %ld, LCP failures %ld (%ld more settled by "
               "complementary pivoting), dynamic-friction fallbacks %ld, impacts grown by their neighbours %ld\n",
               c.contacts.colliding, c.contacts.resting, c.contacts.pivots, c.contacts.failures, c.contacts.lemke_settled,
               c.contacts.friction_fallbacks, c.contacts.merged_impacts);
  std::fprintf(stderr,
               "  resting islands solved by Gauss-Seidel %ld (%ld after pivoting stopped short; "
               "%ld sweeps, %ld subspace steps, %ld solves left unconverged, %ld of them scaled down so as not to add "
               "energy)\n",
               c.contacts.iterative_islands, c.contacts.iterative_fallbacks, c.contacts.sweeps,
               c.contacts.active_set_steps, c.contacts.unconverged_sweeps, c.contacts.passive_scaled);
  if (!c.model_choice.empty()) std::fprintf(stderr, "  contact model: %s\n", c.model_choice.c_str());
  if (!c.target_refinement.empty()) std::fprintf(stderr, "  %s\n", c.target_refinement.c_str());
  const ContactDetector::Work& w = pipeline.detectionWork();
  std::fprintf(stderr, "  work: bodies integrated %ld, broad-phase sweeps %ld, frictional contacts found %ld\n",
               c.bodies_integrated, w.broad_phase_runs, w.frictional_contacts);
  if (w.manifolds_built + w.manifolds_reused > 0)
    std::fprintf(stderr, "  kept manifolds: %ld pair manifolds reused, %ld built by the narrow phase\n",
                 w.manifolds_reused, w.manifolds_built);
  const SleepCounters& s = pipeline.sleepCounters();
  std::fprintf(stderr, "  sleeping: %ld islands fell asleep, %ld woke; %d bodies asleep at the end\n",
               s.islands_slept, s.islands_woken, s.asleep_now);
}

}  // namespace tumble
