// Numerical faults at run time (the third tier of errors, after bad input and missing files): a
// NaN or infinite state, runaway energy, penetration beyond a limit, a body moved farther than its
// velocities allow (motion_check.h), or energy gained in a passive scene (energy_check.h).
// Checked after every step, so a fault is reported the step it happens, with the bodies, the time
// and the stages that ran in that step, instead of being rendered as garbage. The simulator stops on the first fault unless told to keep going;
// either way every fault is counted, for the closing summary.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/contact.h"
#include "dynamics/energy_check.h"
#include "dynamics/motion_check.h"
#include "dynamics/pipeline.h"
#include "dynamics/world.h"

namespace tumble {

struct FaultSettings {
  // Runaway energy: the world's total energy (kinetic + gravitational) may exceed its start value
  // by this share of the energy scale, KE0 + sum m |g| r (r: a body's bounding radius). A passive
  // system (restitution <= 1, constant gravity, static ground) never gains energy; the slack lets
  // integration error and position correction through, while an impulse that adds half again the
  // starting kinetic energy, or lifts every body by half its size, is caught.
  double energy_growth = 0.5;
  // Penetration: a contact deeper than this share of the thinner of the two bodies' thinnest
  // pieces. The tunnelling bound keeps a sub-step's closing below a quarter of the thinnest piece,
  // so a healthy run stays well under a half.
  double depth_share = 0.5;
  // Energy gained above the running minimum (energy_check.h): this share of the scene's energy
  // scale, plus what lifting every moving body by `energy_drift_m` takes (position correction
  // returns what drift took; values measured on every scene, see energy_check.h).
  double energy_gain_share = 1e-3;
  double energy_drift_m = 1e-4;
  // Steps within which a model may pay energy back (energy_check.h): for the time-stepping model
  // the latest a landing's bounce may come (kOwedBounceCarries + 1 steps after the landing,
  // time_stepping/contact_impulses.h); 0 for the Baraff model.
  int energy_repaid_within = 0;

  // The settings for a run of this contact model.
  static FaultSettings forModel(ContactModel model);
};

struct Fault {
  enum class Kind { NonFinite, RunawayEnergy, DeepPenetration, UnexplainedMotion, EnergyGain, Count };
  Kind kind = Kind::NonFinite;
  double time = 0;                   // s: the end of the step where it was found
  long step = 0;                     // 1-based step index
  std::string stages;                // the stages that ran in that step, in order
  std::vector<std::string> bodies;   // the bodies concerned
  std::string detail;                // what was seen, with numbers

  // One line: "numerical failure at t = 1.25 s (step 300; stages detect, collide, ...): ...".
  std::string describe() const;
};

class FaultCheck {
 public:
  explicit FaultCheck(const World& world, FaultSettings settings = {});

  // The first fault in the world after step `step` (NaN first: energies of a NaN state mean
  // nothing), counting it. The pipeline gives the contacts found at the end of the step and,
  // through its stage timers, which stages ran in it.
  std::optional<Fault> afterStep(const World& world, const Pipeline& pipeline, long step);

  long count(Fault::Kind kind) const { return counts_[static_cast<int>(kind)]; }
  long total() const;
  const std::optional<Fault>& first() const { return first_; }
  // "3 faults: 2 runaway energy (first at t = ...), ..."; empty when there were none.
  std::string summary() const;

  // The worst the run came to, fault or not (--stats): measured on what the checks already see.
  struct Extremes {
    double deepest_m = 0;        // m: the deepest contact at the end of any step
    double deepest_time = 0;     // s: when
    double energy_start_j = 0;   // J: kinetic + gravitational (zero at each body's start) + stored
    double energy_end_j = 0;     // J: the same after the last step
    double highest_rise_j = 0;   // J: the most the total ever stood above its start
    double scale_j = 0;          // J: the energy in play, KE0 + sum m |g| r: what a drift is a share of
  };
  const Extremes& extremes() const { return extremes_; }

 private:
  std::optional<Fault> nonFinite(const World& world) const;
  std::optional<Fault> runawayEnergy(const World& world, double stored) const;
  std::optional<Fault> deepPenetration(const World& world, const std::vector<Contact>& contacts) const;
  std::optional<Fault> unexplainedMotion(const World& world, const Pipeline& pipeline);
  std::optional<Fault> energyGain(const World& world, double stored);
  double energyOf(const RigidBody& body, int index) const;
  std::string stagesRun(const std::vector<StageTime>& profile);
  std::optional<Fault> record(Fault fault, const World& world, long step, const std::string& stages);

  FaultSettings settings_;
  std::vector<Eigen::Vector3d> start_x_;   // m: each body's start, the zero of its potential energy
  std::vector<double> start_energy_;       // J: per body
  double energy_limit_ = 0;                // J: above the start total
  double start_total_ = 0;                 // J
  Eigen::Vector3d gravity_;
  std::vector<double> stage_seconds_;      // s: the stage timers after the previous step
  std::vector<BodyExtent> extents_;        // each body's radius and thinnest piece (inf for planes)
  MotionCheck motion_;
  EnergyCheck energy_;
  double last_time_ = 0;                   // s: the world's time after the previous step
  long counts_[static_cast<int>(Fault::Kind::Count)] = {};
  std::optional<Fault> first_;
  Extremes extremes_;
  void measure(const World& world, double stored, const std::vector<Contact>& contacts);
};

}  // namespace tumble
