#include "dynamics/auto/auto_model.h"

#include <algorithm>
#include <cstdio>

#include "dynamics/pipeline.h"

namespace tumble {

StepSettings crowdSettings(const StepSettings& scene) {
  StepSettings s = scene;
  s.model = ContactModel::TimeStepping;
  s.time_stepping_sweeps = kAutoCrowdSweeps;
  s.contact.max_direct_rows = kAutoCrowdPivotRows;
  return s;
}

void AutoModel::start(const World& world, const StepSettings& settings, SharedStages& shared) {
  int moving = 0, free_bodies = 0;
  std::vector<char> touching(world.bodies.size(), 0);
  if (shared.has_contacts) {
    std::vector<Contact> contacts;
    shared.detector.detect(world, settings.contact, contacts);
    for (const Contact& c : contacts) touching[c.a] = touching[c.b] = 1;
  }
  // A joined body is held, not a free landing: a long chain is no crowd (and time stepping's ten
  // sweeps would leave its joints loose).
  for (const Joint& j : world.joints)
    for (int k : {j.a, j.b})
      if (k >= 0) touching[k] = 1;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    if (world.bodies[i].is_static) continue;
    ++moving;
    free_bodies += touching[i] ? 0 : 1;
  }
  // Poisson's and Stronge's laws exist only in the Baraff model: a scene that asks for one asks
  // for that model.
  const bool law = settings.contact.restitution_law != RestitutionLaw::Newton;
  crowd_ = shared.has_contacts && free_bodies >= kAutoCrowd && !law;
  char line[300];
  if (law)
    std::snprintf(line, sizeof line, "Baraff: the scene asks for %s restitution law, which only it has",
                  settings.contact.restitution_law == RestitutionLaw::Poisson ? "Poisson's" : "Stronge's");
  else if (!shared.has_contacts)
    std::snprintf(line, sizeof line, "Baraff: nothing in this scene can touch (%d moving %s)", moving,
                  moving == 1 ? "body" : "bodies");
  else if (crowd_)
    std::snprintf(line, sizeof line,
                  "time stepping (%d Gauss-Seidel sweeps): %d of %d moving bodies start free, a crowd of "
                  "landings (%d or more) that would cut every exact step",
                  kAutoCrowdSweeps, free_bodies, moving, kAutoCrowd);
  else
    std::snprintf(line, sizeof line,
                  "Baraff: %d of %d moving bodies start free, fewer than the %d that make a crowd of landings",
                  free_bodies, moving, kAutoCrowd);
  reason_ = line;
  chosen_ = makeContactModel(crowd_ ? ContactModel::TimeStepping : ContactModel::Baraff);
  run_settings_ = crowd_ ? crowdSettings(settings) : settings;
  const double target = settings.target.penetration_m;
  if (target > 0) {
    run_settings_.contact.tolerance_m = std::min(run_settings_.contact.tolerance_m, target);
    if (shared.has_contacts) refinement_.emplace(world, target);
  }
  chosen_->start(world, run_settings_, shared);
  shared.counters.model_choice = "auto chose " + reason_;
  if (refinement_) shared.counters.target_refinement = refinement_->summary();
}

void AutoModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  run_settings_.dt = settings.dt;   // the only setting a caller may change between steps
  if (!refinement_) {
    chosen_->step(world, run_settings_, shared);
    return;
  }
  refinement_->step(world, run_settings_, shared, *chosen_);
  const StepRefinement::Counters& c = refinement_->counters();
  if (c.retaken_steps != reported_retakes_ || c.missed_steps != reported_misses_) {
    reported_retakes_ = c.retaken_steps;
    reported_misses_ = c.missed_steps;
    shared.counters.target_refinement = refinement_->summary();
  }
}

std::vector<std::string> AutoModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  StepSettings shown = run_settings_;
  shown.dt = settings.dt;
  std::vector<std::string> lines{"model       auto chose " + reason_};
  for (const std::string& l : chosen_->describe(shown, shared)) lines.push_back(l);
  char line[300];
  if (settings.target.penetration_m > 0) {
    std::snprintf(line, sizeof line,
                  "target      penetration %g m: contact tolerance %g m; a step that ends deeper is taken back and "
                  "run again in halves (up to %d sub-steps)",
                  settings.target.penetration_m, shown.contact.tolerance_m, kMaxRefinement);
    lines.push_back(line);
  }
  if (settings.target.energy_drift > 0) {
    std::snprintf(line, sizeof line,
                  "target      energy rise %g of the energy in play: measured, and reported at the end",
                  settings.target.energy_drift);
    lines.push_back(line);
  }
  return lines;
}

}  // namespace tumble
