#include "dynamics/pipeline.h"

#include <cstdio>

#include "dynamics/auto/auto_model.h"
#include "dynamics/baraff/baraff_model.h"
#include "dynamics/penalty/penalty_model.h"
#include "dynamics/time_stepping/time_stepping_model.h"

namespace tumble {

std::unique_ptr<ContactModelStep> makeContactModel(ContactModel model) {
  switch (model) {
    case ContactModel::Baraff: return std::make_unique<BaraffModel>();
    case ContactModel::TimeStepping: return std::make_unique<TimeSteppingModel>();
    case ContactModel::Penalty: return std::make_unique<PenaltyModel>();
    case ContactModel::Auto: return std::make_unique<AutoModel>();
  }
  return nullptr;
}

Pipeline::Pipeline(const World& world, const StepSettings& settings)
    : shared_(world), model_(makeContactModel(settings.model)) {
  model_->start(world, settings, shared_);
}

void Pipeline::step(World& world, const StepSettings& settings) {
  shared_.peak_speed.assign(world.bodies.size(), 0.0);
  shared_.peak_spin.assign(world.bodies.size(), 0.0);
  model_->step(world, settings, shared_);
  settleAtRest(world, settings);
}

// After a whole step, so that a body is judged by the velocity the step leaves it with.
void Pipeline::settleAtRest(World& world, const StepSettings& settings) {
  if (!shared_.has_contacts || !settings.sleep.enabled) return;
  bool slept = false;
  shared_.timed(Sleep, [&] {
    slept = shared_.sleep.settle(world, shared_.contacts, settings.sleep, settings.dt, shared_.detector);
  });
  // The sleepers' contacts with each other and the ground are gone from the next detection.
  if (slept) shared_.contacts_fresh = false;
}

std::vector<std::string> Pipeline::describe(const StepSettings& settings) const {
  std::vector<std::string> lines = model_->describe(settings, shared_);
  // Auto steers by the target and says how (auto_model.h); a model the scene names runs as asked.
  if (settings.target.any() && settings.model != ContactModel::Auto)
    lines.push_back("target      measured and reported at the end, not steered by: the scene names its contact "
                    "model (auto refines its step to meet a penetration target)");
  if (!shared_.has_contacts) return lines;
  char line[200];
  if (settings.sleep.enabled)
    std::snprintf(line, sizeof line,
                  "sleep       islands slower than %g m/s and %g rad/s for %g s, resting on something "
                  "fixed, freeze until touched",
                  settings.sleep.speed_m_s, settings.sleep.spin_rad_s, settings.sleep.after_s);
  else
    std::snprintf(line, sizeof line, "sleep       off: every body is simulated to the end");
  lines.push_back(line);
  return lines;
}

}  // namespace tumble
