#include "app/stats_file.h"

#include "io/atomic_file.h"

namespace tumble {

void checkStatsOutput(const std::filesystem::path& path, bool overwrite) {
  checkReplaceable(path);
  std::error_code ec;
  if (!overwrite && std::filesystem::exists(path, ec))
    throwCantWrite(path, "it already exists (use -y/--overwrite to replace it)");
}

nlohmann::json simulationStats(const Simulator& simulator, const SimulationPlan& plan, double simulated_s) {
  const Pipeline& pipeline = simulator.pipeline();
  nlohmann::json stages = nlohmann::json::object();
  for (const StageTime& s : pipeline.profile()) stages[s.name] = s.seconds;
  const PipelineCounters& c = pipeline.counters();
  const ContactSolveStats& k = c.contacts;
  const SleepCounters& sleep = pipeline.sleepCounters();
  const FaultCheck::Extremes& x = simulator.faults().extremes();
  nlohmann::json out = {
      {"simulated_s", simulated_s},
      {"frames", plan.frames},
      {"steps", static_cast<long>(plan.frames - 1) * plan.steps_per_frame},
      {"dt_s", plan.step.dt},
      {"stages_s", stages},
      {"steps_detail",
       {{"substeps", c.substeps}, {"back_steps", c.back_steps}, {"bisection_evaluations", c.bisection_evaluations},
        {"projections", c.projections}, {"capped_projections", c.capped_projections},
        {"stuck_substeps", c.stuck_substeps}, {"inconsistent_pairs", c.inconsistent_pairs},
        {"contact_work_paid", c.contact_work_paid}, {"resolved_for_outrun", c.resolved_for_outrun},
        {"split_steps", c.split_steps},
        {"bodies_integrated", c.bodies_integrated}}},
      {"contacts",
       {{"colliding", k.colliding}, {"resting", k.resting}, {"lcp_pivots", k.pivots}, {"lcp_failures", k.failures},
        {"lcp_settled_by_lemke", k.lemke_settled},
        {"friction_fallbacks", k.friction_fallbacks}, {"iterative_islands", k.iterative_islands},
        {"iterative_fallbacks", k.iterative_fallbacks}, {"sweeps", k.sweeps},
        {"unconverged_sweeps", k.unconverged_sweeps}, {"active_set_steps", k.active_set_steps},
        {"passive_scaled", k.passive_scaled},
        {"merged_impacts", k.merged_impacts},
        {"frictional_found", pipeline.detectionWork().frictional_contacts},
        {"manifolds_reused", pipeline.detectionWork().manifolds_reused},
        {"manifolds_built", pipeline.detectionWork().manifolds_built}}},
      {"sleep", {{"islands_slept", sleep.islands_slept}, {"islands_woken", sleep.islands_woken},
                 {"asleep_at_end", sleep.asleep_now}}},
      // The drift is the most the total energy stood above its start, as a share of the energy in
      // play (the fault check's scale): a passive scene never gains, so this is the error.
      {"energy", {{"start_j", x.energy_start_j}, {"end_j", x.energy_end_j}, {"highest_rise_j", x.highest_rise_j},
                  {"scale_j", x.scale_j}, {"drift", x.scale_j > 0 ? x.highest_rise_j / x.scale_j : 0.0}}},
      {"deepest_penetration", {{"m", x.deepest_m}, {"t_s", x.deepest_time}}},
      {"faults", simulator.faults().total()},
  };
  if (!c.model_choice.empty()) out["contact_model"] = c.model_choice;
  return out;
}

void writeStatsFile(const std::filesystem::path& path, bool overwrite, const nlohmann::json& stats) {
  writeFileWhole(path, stats.dump(2) + "\n", overwrite);
}

}  // namespace tumble
