#include "dynamics/simulator.h"

#include "base/error.h"

namespace tumble {

BodySample sampleOf(const RigidBody& body) {
  return {body.x, body.q, body.velocity(), body.angularVelocity()};
}

Simulator::Simulator(World world, const SimulationPlan& plan)
    : world_(std::move(world)),
      plan_(plan),
      pipeline_(world_, plan.step),
      faults_(world_, FaultSettings::forModel(pipeline_.runningModel(plan.step))) {
  if (plan.step.target.any())
    target_.emplace(world_, plan.step.target, FaultSettings::forModel(pipeline_.runningModel(plan.step)).energy_repaid_within);
}

// A fault stops the run with Error(Software) the step it happens, unless the plan keeps going.
void Simulator::checkFaults() {
  std::optional<Fault> fault = faults_.afterStep(world_, pipeline_, steps_);
  if (fault && !plan_.keep_going)
    throw Error(ExitCode::Software, fault->describe() + " (--keep-going renders anyway)");
}

void Simulator::advanceFrame(const std::function<void(const World&)>& on_step) {
  for (int i = 0; i < plan_.steps_per_frame; ++i) {
    pipeline_.step(world_, plan_.step);
    world_.time = static_cast<double>(++steps_) * plan_.step.dt;  // exact, never a running sum
    checkFaults();
    if (target_) target_->afterStep(world_, pipeline_);
    if (on_step) on_step(world_);
  }
}

Trajectory Simulator::run(const std::function<void(int)>& on_frame,
                          const std::function<void(const World&)>& on_step) {
  Trajectory out;
  for (const RigidBody& b : world_.bodies) out.body_names.push_back(b.name);
  out.times.reserve(plan_.frames);
  out.frames.reserve(plan_.frames);
  for (int frame = 1; frame <= plan_.frames; ++frame) {
    if (frame > 1) advanceFrame(on_step);
    // Frame k is at (k-1) * interval exactly, not the sum of dt's, so times never drift.
    out.times.push_back((frame - 1) * plan_.step.dt * plan_.steps_per_frame);
    std::vector<BodySample>& samples = out.frames.emplace_back();
    samples.reserve(world_.bodies.size());
    for (const RigidBody& b : world_.bodies) samples.push_back(sampleOf(b));
    if (on_frame) on_frame(frame);
  }
  return out;
}

}  // namespace tumble
