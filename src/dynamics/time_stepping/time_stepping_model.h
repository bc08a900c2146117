// The time-stepping contact model (Moreau 1988; Stewart and Trinkle 1996): one velocity-level
// impulse problem per step, never cut. Symplectic Euler in the momenta. A step:
//
//   detect      contacts within each body's reach (a speculative margin)   shared_stages.h
//   correct     project out residual penetration                          drift_projection.h
//   forces      gravity as an impulse                                     gravity.h
//   resting     the contact impulses (restitution, friction pyramid),     contact_impulses.h
//               with a world's joints in the same problem                 joints/contact_joint_lcp.h
//   integrate   free motion of every body over dt with its new momenta    integrator.h
//               (the scene's integrator turns the bodies, gyroscopic term included)
//   joints      their position drift projected out                         joints/joint_projection.h
#pragma once

#include <vector>

#include "dynamics/contact_model.h"
#include "dynamics/time_stepping/contact_impulses.h"
#include "dynamics/time_stepping/drift_projection.h"

namespace tumble {

class TimeSteppingModel final : public ContactModelStep {
 public:
  void start(const World& world, const StepSettings& settings, SharedStages& shared) override;
  void step(World& world, const StepSettings& settings, SharedStages& shared) override;
  std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const override;
  StepImpulses lastImpulses() const override { return {&impulses_.memory(), last_dt_}; }

 private:
  ContactImpulses impulses_;
  double last_dt_ = 0;             // s: the last step's length (refined steps are shorter)
  DriftProjection projection_;
  std::vector<double> reach_;      // how far each body can travel in the step
  std::vector<Eigen::Vector3d> spin_;   // each body's angular velocity (body_extent.h, bodySpins)
  std::vector<double> approach_;   // per contact: normal approach speed before gravity's impulse
  std::string joints_line_;        // for `tumble check`; empty without joints
};

}  // namespace tumble
