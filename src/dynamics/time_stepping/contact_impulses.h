// The contact impulses of the time-stepping model (Moreau 1988; Stewart and Trinkle 1996; the
// non-smooth time stepping of the contact-mechanics literature; projected Gauss-Seidel with
// friction as in Xiang's "Robot Control and Physical Simulation", 2020): one velocity-level
// impulse problem per step instead of going back to each first contact (two where a step holds an
// impact: the impacts first, then the load; applyImpacts below). For each contact with gap
// phi = -depth (contacts are found within a speculative margin, so phi > 0 for pairs about to
// touch):
//
//   normal    v_n+ >= -max(phi, 0) / dt     a gap may close within the step, never overshoot;
//             v_n+ >= e u                   a touching contact that approached at u bounces
//   friction  two tangent rows, |p_t| <= mu p_n each (a friction pyramid), v_t+ = 0 while inside
//
// solved island by island (island_impulses.h) warm-started from the last step's impulses
// (impulse_memory.h). Penetration is not pushed apart by velocity (Baumgarte adds energy): the
// model projects positions instead (drift_projection.h).
//
// Restitution with a speculative margin: a landing whose gap closes during the step arrives at
// phi = 0 with the small speed that just closes it; its approach speed u is remembered and the
// bounce e u is given the next step, when the contact touches. The bounce is therefore one step
// late (first order in dt), as every quantity of this model is.
#pragma once

#include <span>
#include <vector>

#include "dynamics/body_snapshot.h"
#include "dynamics/contact.h"
#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

// Gauss-Seidel's rate is set by the island's mass ratio: a 35 kg steel shard resting on a 76 g one
// on the ground (465:1) was left approaching it at 1.2 m/s by ten sweeps, step after step, and
// the projection lifted it back out each time, adding energy. A speed setting
// (isSpeedSetting) pivots the small islands its sweeps leave unconverged only from this ratio of
// heaviest to lightest moving body; a pile of equal boxes keeps the sweeps' answer (pivoting its
// many small islands tripled its time).
inline constexpr double kSweepsMassRatio = 4;

// How many steps a landing's bounce is carried while the contact stays short of touching (within
// the margin, pressed by a normal impulse, its gap above the tolerance). One covers a landing that
// rounding leaves a hair apart. Carried for ever, a steel ball landing at 11.5 m/s on a block and
// then pressing on it a few micrometres apart was owed its bounce for 13 steps, and took 2.3 m/s
// off the block it had long been riding with: 65 J from nowhere. So a landing's bounce comes at
// most kOwedBounceCarries + 1 steps after the step that closed its gap.
inline constexpr int kOwedBounceCarries = 1;

class ContactImpulses {
 public:
  // Finds this step's impacts among `contacts`: a touching contact approaching faster than
  // `min_bounce_speed` (contact_solve_common.h), or owed a landing's bounce. `approach` is each
  // contact's normal approach speed (m/s, > 0 closing) before the step's applied impulses, the
  // speed a bounce reverses. Call before applyImpacts() and apply().
  void prepare(const World& world, const std::vector<Contact>& contacts, const std::vector<double>& approach,
               const StepSettings& settings, const BounceThreshold& min_bounce_speed);
  // The impact phase, before the step's applied impulses (gravity): each island with an impact is
  // solved with its bounces as targets, from a zero start, and its impulses applied. Returns whether
  // it solved any (then apply() gives no bounce again). Not for a speed setting (one solve a step
  // by choice) or with joints (their one problem with the contacts).
  //
  // Solved in one problem with the step's load, an impact shares the solve with the friction the
  // resting contacts carry under gravity's impulse (mu m g dt): a ball rolling into a wall had its
  // spin braked by the ground in the impact's own solve and rolled away 3.1 % too fast at 1 m/s and
  // 30 % at 5 cm/s. (A rocking block's landing closes within its step through the speculative margin,
  // so this does not reach it: docs/known-limits.md.) Impacts first and the load after is the order
  // of E. Guendelman, R. Bridson and R. Fedkiw, "Nonconvex rigid bodies with stacking" (2003):
  // collision, then the velocity update, then the contact (e = 0) solve. The impact's impulses are
  // no warm start for the next step (an impact owes it nothing); they are recorded beside the
  // load's, drawn with the contact's force.
  bool applyImpacts(World& world, const std::vector<Contact>& contacts, const StepSettings& settings,
                    ContactSolveStats& stats);
  // Applies this step's contact impulses to the momenta of `world`, whose velocities already hold
  // the step's applied impulses (gravity) and its impacts' (`bounces` false: no bounce targets).
  // The next step's warm start is not touched until remember().
  void apply(World& world, const std::vector<Contact>& contacts, const std::vector<double>& approach,
             const StepSettings& settings, bool bounces, ContactSolveStats& stats);
  // Keeps the impulses of the last apply() for the next step's warm start (a step solved again
  // from its start keeps only its last solve's).
  void remember() { memory_.replace(records_); }
  // This step's impulses (N s on B, world), as the next step's warm start will find them.
  const ImpulseMemory& memory() const { return memory_; }

 private:
  struct IslandScratch;
  // want_ from the gaps, and the bounces where `bounces`.
  void targets(const std::vector<Contact>& contacts, double dt, bool bounces);
  void cacheVelocities(const World& world);
  // The b of a set's rows (contacts from `first`): each row's velocity now, less its contact's
  // normal target.
  void velocityTerms(std::span<const Contact* const> set, const ContactRows& rows, const Contact* first,
                     Eigen::Ref<Eigen::VectorXd> b) const;
  // One island's rows and b in `scratch`, its first guess in scratch.p; the answer left there.
  void solveIsland(const World& world, std::span<const Contact* const> island, IslandScratch& scratch,
                   const StepSettings& settings, double gravity_dt, ContactSolveStats& own);

  ImpulseMemory memory_;
  // Buffers of a step, kept for the next: a warm step allocates nothing (the joints' one problem
  // and a small island's pivoting solve aside; tests/dynamics/test_step_allocations.cpp).
  std::vector<Eigen::Vector3d> velocity_, spin_;   // per body
  std::vector<const ImpulseRecord*> last_;         // per contact: last step's record, or null
  std::vector<double> want_, owed_;                // per contact: normal velocity target, bounce owed
  std::vector<double> bounce_;                     // per contact: an impact's bounce e u, else -1
  std::vector<Eigen::Vector3d> impact_impulse_;    // per contact: the impact phase's (on B, world)
  bool impacts_ = false;
  bool islands_split_ = false;                     // islands_ already split for prepare()'s contacts
  std::vector<const Contact*> all_;
  std::vector<Eigen::Vector3d> impulse_;           // per contact: on B, world axes
  std::vector<double> normal_impulse_;
  ContactIslands islands_;
  std::vector<ContactSolveStats> island_stats_;
  std::vector<ImpulseRecord> records_;
  // With joints: the bodies before the solve and after the joints' impulses, for an answer whose
  // bounces add kinetic energy (contact_impulses.cpp).
  BodySnapshot before_, joined_;
};

}  // namespace tumble
