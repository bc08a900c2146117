// The regularised (penalty) contact model: bodies overlap a little, and a force law of the
// overlap δ and its rate (force_laws.h), with a regularised friction law (friction_laws.h), pushes
// them apart. No impulses, no complementarity problem: an ODE, stiff where the contacts are, so it
// is integrated in sub-steps as short as the stiffest contact needs. A step:
//
//   detect      contacts within each body's reach over the step (as the time-stepping model)
//   collide     each contact point becomes a spring anchored in both bodies (its core points and
//               its normal, carried with the bodies: Bullet's persistent-manifold refresh), with
//               its law's stiffness, damping and friction, and the closing speed it started with
//   sub-steps   until the step is done: each point's overlap and rate from the bodies' poses, its
//               normal and friction forces, gravity; a sub-step no longer than the contacts'
//               stability allows (below); velocity Verlet over it
//
// The sub-step: explicit integration of a spring of frequency ω is accurate when ω h is small,
// and of a damper of rate γ = c / m stable when γ h < 2. A body's contacts add up (Gershgorin:
// the largest frequency of the coupled springs is at most the largest sum over a body's springs of
// k / m_eff), so per body the sums of k / m_eff, c / m_eff and the friction law's slope f_n / m_eff
// bound the step: h <= 0.1 / ω, h <= 0.5 / γ. A Hertz-type spring stiffens as it closes; it is
// bounded by its stiffness at the overlap its closing speed and its point's weight would reach. A
// point about to touch cuts the sub-step where it touches, so its impact starts at δ = 0 with its
// true closing speed.
// When a contact needs more than `max_substeps` sub-steps per step, the run stops with the pair,
// its stiffness and the step it needs: never a silent blow-up.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_model.h"
#include "dynamics/penalty/force_laws.h"
#include "dynamics/penalty/friction_laws.h"

namespace tumble {

class PenaltyModel final : public ContactModelStep {
 public:
  // Refuses a world with joints (exit 65): the model has no rows to hold them, and stiff springs in
  // their place would set its sub-step by the joints' stiffness (the scene loader refuses such a
  // scene first, pointing at "joints").
  void start(const World& world, const StepSettings& settings, SharedStages& shared) override;
  void step(World& world, const StepSettings& settings, SharedStages& shared) override;
  std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const override;
  double storedEnergy() const override { return stored_energy_; }

  // One contact point as a spring between two bodies.
  struct Spring {
    int a = -1, b = -1;
    PiecePair pair;
    Eigen::Vector3d core_a = Eigen::Vector3d::Zero(), core_b = Eigen::Vector3d::Zero();   // body frames: the surfaces' core points (rounded pieces'
                                      // centres or axes; polyhedra's surface points)
    Eigen::Vector3d normal_b = Eigen::Vector3d::UnitZ();   // B's frame: from A to B
    double radius_a = 0, radius_b = 0;
    NormalLawState law;
    FrictionLawState friction;
    double inverse_mass = 0;          // 1 / m_eff along the normal at the point (both bodies)
    bool touching = false;            // δ > 0 at the last evaluation: its closing speed is set
    // At the last evaluation (world frame):
    Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ(), slip = Eigen::Vector3d::Zero();
    double depth = 0, rate = 0, normal_force = 0;
  };
  const std::vector<Spring>& springs() const { return springs_; }

 private:
  void buildSprings(const World& world, const StepSettings& settings, const SharedStages& shared);
  void evaluate(const World& world);
  void addForces(const World& world, std::vector<Wrench>& wrenches, double h) const;
  // The longest sub-step the springs allow (s), at most `remaining`.
  double stableSubstep(const World& world, double remaining, const Eigen::Vector3d& gravity);
  [[noreturn]] void refuse(const World& world, const StepSettings& settings, double needed) const;

  std::vector<Spring> springs_, last_springs_;
  std::vector<double> reach_;
  std::vector<double> sum_stiffness_, sum_damping_, sum_friction_;   // per body, for the sub-step
  std::vector<double> impact_damping_;                              // per spring: c / m_eff while it strikes
  std::vector<double> sum_slip_mass_;                               // per body: touching points' tangential 1/m_eff
  std::vector<Wrench> idle_;                                        // no force: the drift
  std::vector<Wrench> start_wrenches_;                              // a sub-step's forces at its start
  int stiffest_ = -1;                                               // spring that set the last sub-step
  double stable_ = 0;                                               // s: the last sub-step the springs allowed
  double stored_energy_ = 0;
};

}  // namespace tumble
