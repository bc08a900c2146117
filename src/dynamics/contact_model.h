// The one interface every contact model implements. A model owns its step and its state; the
// Pipeline (pipeline.h) owns what all models share (shared_stages.h) and hands each step to the
// scene's model. Adding a model means adding a folder beside baraff/ and time_stepping/ and one
// case to makeContactModel (pipeline.cpp).
#pragma once

#include <string>
#include <vector>

#include "dynamics/settings.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

class ImpulseMemory;

// Each contact's impulse over the model's last step, and that step's length (s): an impulse over
// it divided by it is the contact's force (a resting force, or an impact spread over the step).
struct StepImpulses {
  const ImpulseMemory* memory = nullptr;   // null where the model keeps none
  double span_s = 0;
};

class ContactModelStep {
 public:
  virtual ~ContactModelStep() = default;
  // Called once by the Pipeline before the first step, with the world as the scene left it.
  virtual void start(const World& /*world*/, const StepSettings& /*settings*/, SharedStages& /*shared*/) {}
  // Advances `world` by settings.dt, leaving the contacts of its end state in `shared.contacts`
  // (or `shared.contacts_fresh` false when they must be detected again).
  virtual void step(World& world, const StepSettings& settings, SharedStages& shared) = 0;
  // One line per stage this model runs in this scene, in order (for `tumble check`).
  virtual std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const = 0;
  // Energy the model holds outside the bodies' motion at the end of the step (J): a compliant
  // contact's spring. The energy check counts it, so an elastic bounce is not energy from nowhere.
  virtual double storedEnergy() const { return 0; }
  // Each contact's impulse of the last step (N s on B), read by overlays; none where the model
  // keeps none (the penalty model's springs).
  virtual StepImpulses lastImpulses() const { return {}; }
  // The model that actually runs the steps: the automatic one names its choice.
  virtual ContactModel running(ContactModel asked) const { return asked; }
};

}  // namespace tumble
