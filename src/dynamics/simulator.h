// Runs the pipeline from the initial world to the last frame, sampling every body at every frame
// (or every step), and stops with a clear error the step a state turns NaN or infinite.
#pragma once

#include <functional>
#include <optional>

#include "dynamics/fault_check.h"
#include "dynamics/pipeline.h"
#include "dynamics/settings.h"
#include "dynamics/target_watch.h"
#include "dynamics/trajectory.h"
#include "dynamics/world.h"

namespace tumble {

struct SimulationPlan {
  StepSettings step;
  int steps_per_frame = 8;
  int frames = 120;            // frame 1 is the initial state at t = 0
  bool keep_going = false;     // on a numerical fault: count it and go on, instead of stopping
};

BodySample sampleOf(const RigidBody& body);

class Simulator {
 public:
  Simulator(World world, const SimulationPlan& plan);

  // Steps to the next frame. `on_step` (if set) sees the world after every step.
  void advanceFrame(const std::function<void(const World&)>& on_step = {});
  // Runs every frame and returns the samples at frame times; `on_frame` reports progress.
  Trajectory run(const std::function<void(int frame)>& on_frame = {},
                 const std::function<void(const World&)>& on_step = {});

  const World& world() const { return world_; }
  // While set, the contact model appends the impacts it resolves (for overlays; frame_record.h).
  void setImpactLog(std::vector<ImpactMark>* log) { pipeline_.setImpactLog(log); }
  // While set, the Baraff model keeps its back-steps' brackets (for overlays; back_step_log.h).
  void setBackStepLog(BackStepLog* log) { pipeline_.setBackStepLog(log); }
  const Pipeline& pipeline() const { return pipeline_; }
  const FaultCheck& faults() const { return faults_; }
  // The run measured against the scene's accuracy target; empty when the scene sets none.
  const std::optional<TargetWatch>& target() const { return target_; }

 private:
  void checkFaults();

  World world_;
  SimulationPlan plan_;
  Pipeline pipeline_;
  FaultCheck faults_;
  std::optional<TargetWatch> target_;
  long steps_ = 0;
};

}  // namespace tumble
