// The simulation step. The Pipeline holds what every contact model shares (shared_stages.h:
// detection, waking, the stage profile and counters) and hands each step to the scene's contact
// model (contact_model.h), each in a folder of its own:
//
//   baraff/          event-driven: sub-steps cut at first contacts, impulses, resting-force LCP
//   time_stepping/   velocity-level impulses, one problem per step, never cut
//   penalty/         regularised force laws of the overlap, in sub-steps the contacts' stiffness sets
//   auto/            Baraff, or time stepping for a crowd of landings, chosen at the start
//
// After the model's step, the one stage both share: islands at rest fall asleep (sleeping.h).
// "Model only what a scene needs": without gravity there is no force stage, without anything that
// can touch there is no contact stage, static bodies are never integrated.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dynamics/contact_model.h"
#include "dynamics/settings.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

// The one switch on the contact model.
std::unique_ptr<ContactModelStep> makeContactModel(ContactModel model);

class Pipeline {
 public:
  Pipeline(const World& world, const StepSettings& settings);
  void step(World& world, const StepSettings& settings);

  // One line per stage: what it does in this scene (for `tumble check`).
  std::vector<std::string> describe(const StepSettings& settings) const;
  const std::vector<StageTime>& profile() const { return shared_.profile; }
  const PipelineCounters& counters() const { return shared_.counters; }
  // The contacts found at the end of the last step (for overlays and tests).
  const std::vector<Contact>& contacts() const { return shared_.contacts; }
  const SleepCounters& sleepCounters() const { return shared_.sleep.counters(); }
  const ContactDetector::Work& detectionWork() const { return shared_.detector.work(); }
  // The contact model that runs the steps (auto's choice, when the scene asked for auto).
  ContactModel runningModel(const StepSettings& settings) const { return model_->running(settings.model); }
  // Energy held in compliant contacts (J; the penalty model's springs), for the energy checks.
  double storedEnergy() const { return model_->storedEnergy(); }
  // Each body's largest speed and spin within the last step (shared_stages.h; zero where a model
  // has no sub-steps).
  const std::vector<double>& peakSpeeds() const { return shared_.peak_speed; }
  const std::vector<double>& peakSpins() const { return shared_.peak_spin; }
  // Each contact's impulse over the last step, where the model keeps them (contact_model.h).
  StepImpulses lastImpulses() const { return model_->lastImpulses(); }
  // While set, the model appends the impacts it resolves (shared_stages.h, ImpactMark).
  void setImpactLog(std::vector<ImpactMark>* log) { shared_.impact_log = log; }
  // While set, the Baraff model keeps the brackets of its back-steps (back_step_log.h).
  void setBackStepLog(BackStepLog* log) { shared_.back_step_log = log; }
  // The detection the steps run: its broad phase's boxes and pairs as of its last sweep, read by
  // the broad_phase overlay (frame_record.h).
  const ContactDetector& detector() const { return shared_.detector; }

 private:
  void settleAtRest(World& world, const StepSettings& settings);

  SharedStages shared_;
  std::unique_ptr<ContactModelStep> model_;
};

}  // namespace tumble
