#include "dynamics/auto/auto_model.h"

#include <cstdio>

#include "dynamics/pipeline.h"

namespace tumble {

StepSettings crowdSettings(const StepSettings& scene) {
  StepSettings s = scene;
  s.model = ContactModel::TimeStepping;
  s.time_stepping_sweeps = kAutoCrowdSweeps;
  s.contact.max_direct_rows = 0;
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
  crowd_settings_ = crowdSettings(settings);
  chosen_->start(world, crowd_ ? crowd_settings_ : settings, shared);
  shared.counters.model_choice = "auto chose " + reason_;
}

void AutoModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  if (!crowd_) {
    chosen_->step(world, settings, shared);
    return;
  }
  crowd_settings_.dt = settings.dt;   // the only setting a caller may change between steps
  chosen_->step(world, crowd_settings_, shared);
}

std::vector<std::string> AutoModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  std::vector<std::string> lines{"model       auto chose " + reason_};
  for (const std::string& l : chosen_->describe(crowd_ ? crowd_settings_ : settings, shared)) lines.push_back(l);
  return lines;
}

}  // namespace tumble
