// The event-driven contact model (Baraff 1994; the rigid-body lecture notes of Yang 2020): a step
// of dt is cut into sub-steps at each first contact, found by back-stepping, and where a body could
// pass through a piece it may meet (the tunnelling bound). Each sub-step:
//
//   detect      broad phase + narrow phase (within the margin)    shared_stages.h
//   collide     classify; Newton impulses on colliding contacts   collisions.h
//   forces      gravity                                           gravity.h
//   resting     contact forces: LCP + Coulomb friction            resting_forces.h
//   integrate   (x, q, P, L) over the sub-step, cut by the         integrator.h,
//               tunnelling bound                                   tunnelling_bound.h
//   detect      the contacts at the end of the sub-step
//   back-step   bisection to the first contact if it ends too deep back_step.h
//   correct     project out residual penetration, in passes on the    drift_correction.h
//               contacts of the end state, while a pass moves something
//   joints      (a world with joints) their forces are evaluated at    joints/joint_forces.h
//               every integrator stage, with the resting contacts'     joints/contact_joint_lcp.h
//               rows in the resting solve; impacts are solved with     joints/joint_mobility.h
//               the joints holding; their drift is projected out       joints/joint_projection.h
#pragma once

#include <vector>

#include "dynamics/baraff/back_step.h"
#include "dynamics/baraff/contact_work_bound.h"
#include "dynamics/baraff/drift_correction.h"
#include "dynamics/baraff/resting_forces.h"
#include "dynamics/baraff/tunnelling_bound.h"
#include "dynamics/body_snapshot.h"
#include "dynamics/contact_model.h"

namespace tumble {

class BaraffModel final : public ContactModelStep {
 public:
  void start(const World& world, const StepSettings& settings, SharedStages& shared) override;
  void step(World& world, const StepSettings& settings, SharedStages& shared) override;
  std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const override;
  // The resting solve's impulses, over the step given (resting_forces.h: step_s).
  StepImpulses lastImpulses() const override { return {&resting_memory_.last, last_dt_}; }

 private:
  // One sub-step of at most `remaining` seconds; returns its length.
  double substep(World& world, const StepSettings& settings, SharedStages& shared, double remaining);
  void correctJoints(World& world, SharedStages& shared);

  RestingMemory resting_memory_;   // warm start of resting islands too large to pivot
  double last_dt_ = 0;             // s: the last step's length (refined steps are shorter)
  TunnellingBound tunnelling_;
  BackStepper back_step_;
  DriftCorrection correction_;
  ContactWorkBound work_bound_;
  BodySnapshot start_state_;       // the state at the sub-step's start, for back-stepping
  std::vector<Contact> contacts_end_;
  std::vector<PiecePair> pairs_end_;
  std::vector<char> lifting_;      // per contact at the start: separating as the sub-step starts
  std::string joints_line_;        // for `tumble check`; empty without joints
};

}  // namespace tumble
