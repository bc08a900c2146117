// The time-stepping contact model (Moreau 1988; Stewart and Trinkle 1996): one velocity-level
// impulse problem per step, never cut. Symplectic Euler in the momenta. A step:
//
//   forces      gravity as an impulse                                     gravity.h
//   resting     the contact impulses (restitution, friction pyramid),     contact_impulses.h
//               with a world's joints in the same problem                 joints/contact_joint_lcp.h
//   (again)     the step from its start, with the contacts of the motion   outrun_contacts.h
//               the solve gave, where it sent a body past its reach
//   integrate   free motion of every body over dt with its new momenta    integrator.h
//               (the scene's integrator turns the bodies, gyroscopic term included)
//   detect      contacts within each body's reach (a speculative margin)   shared_stages.h
//   correct     project out residual penetration                          drift_projection.h
//   joints      their position drift projected out                         joints/joint_projection.h
//   (split)     a step that moved a body farther than its speeds explain,  step_split.h
//               taken back and run again as two halves
//
// The step's contacts are the ones the last step ended with; the first step, and one after
// anything changed the bodies between steps (sleep, a step taken back, the joints' projection) or
// of another length, detects and corrects first.
//
// Why detect and correct at the end (post-stabilisation: M. B. Cline and D. K. Pai,
// "Post-stabilization for rigid body simulation with contact and constraints", 2003): the state a
// step ends in is the one frames, trajectories, the fault check and sleeping see, and the rows
// hold contacts to first order only. Two halves of a brick struck by a steel ball slide along
// each other at 8 m/s turning at 70 rad/s: their shared face turns by 0.07 rad within a 1 ms
// step, and the slide closes it by about |w| |v_t| dt^2. Corrected only at the start of the next
// step, the overlap at a step's end reached 1.4 mm and stayed above 1 mm for 4 steps; corrected
// at the end, no step ends deeper than 0.17 mm. The stages run in the same sequence as before
// (detect, correct, solve, integrate, detect, ...): one detection more per run, and one more per
// step where a joint's projection moved a body after it.
#pragma once

#include <vector>

#include "dynamics/body_snapshot.h"
#include "dynamics/contact_model.h"
#include "dynamics/time_stepping/contact_impulses.h"
#include "dynamics/time_stepping/drift_projection.h"
#include "dynamics/time_stepping/outrun_contacts.h"
#include "dynamics/time_stepping/step_split.h"

namespace tumble {

class TimeSteppingModel final : public ContactModelStep {
 public:
  void start(const World& world, const StepSettings& settings, SharedStages& shared) override;
  void step(World& world, const StepSettings& settings, SharedStages& shared) override;
  std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const override;
  StepImpulses lastImpulses() const override { return {&impulses_.memory(), last_dt_}; }

 private:
  // One step of settings.dt, never split.
  void stepOnce(World& world, const StepSettings& settings, SharedStages& shared);
  // Detection (with waking the sleepers it finds touched) and the drift projection.
  void detectAndCorrect(World& world, const StepSettings& settings, SharedStages& shared);

  ContactImpulses impulses_;
  double last_dt_ = 0;             // s: the last step's length (refined steps are shorter)
  DriftProjection projection_;
  std::vector<double> reach_;      // how far each body can travel in the step
  std::vector<Eigen::Vector3d> spin_;   // each body's angular velocity (body_extent.h, bodySpins)
  std::vector<double> approach_;   // per contact: normal approach speed before gravity's impulse
  std::string joints_line_;        // for `tumble check`; empty without joints
  BodySnapshot step_start_;       // the state the step starts in, for a solve taken again
  OutrunContacts outrun_found_;    // the contacts of a solve that outran the step's reach
  std::vector<Contact> outrun_;    // the step's contacts with those
  BodySnapshot end_state_;         // the state the last step ended in, its contacts detected
  double detected_dt_ = 0;         // s: the step length those contacts were detected for
  StepSplit split_;
};

}  // namespace tumble
