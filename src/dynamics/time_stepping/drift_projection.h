// Drift projection for the time-stepping model: positions only, pair by pair, repeated in passes
// (tuning::kProjectionPasses, then up to kProjectionMaxPasses over the pairs still far deeper than
// the tolerance: a landing), each pass reading the depths the earlier pushes left (a contact's
// depth changes by the relative displacement of its two material points along its normal). One
// pass, as the Baraff model makes after every sub-step, cannot keep up under a load: in a column
// of boxes each push down into the box below is undone by the push up from it, and in the
// 1000-box pile pairs sank into each other by 6-8 cm over seconds.
//
// A pair is pushed apart at its points, not as a whole: each point deeper than the tolerance
// takes a push along its normal of the least mass-weighted size, translation and rotation together,
// that brings it back to half the tolerance (the pair's effective mass along the normal at the
// point), its points in turn a few times over (projected Gauss-Seidel on the pair's positions), so
// a face sunk level comes out level and a corner sunk alone turns out. This is the position solve
// of E. Catto's Box2D ("Iterative Dynamics with Temporal Coherence", 2005, and its later
// position constraints) and of M. Mueller et al., "Position Based Dynamics" (2007). Pushed by
// translation alone, a plank pitched onto one support was lifted whole by its corner's depth,
// four times what turning it out takes for a plank, and left pitched; a crib's top planks rocked
// and slid at up to 5 cm/s, fed by those lifts (1e-4 J a step across the crib, tripping the
// energy-gain check), where the crib now comes to rest within 0.8 s.
//
// Drift turns a body by far less than a milliradian (a plank's corner 50 um deep, 5 cm from its
// centre). A push that would turn a body more (tuning::kProjectionMaxTurn) is an overlap a violent
// step left, a fragment struck at 60 m/s, and is made by translation alone: turned that far, the
// fragment drives its other corners into neighbours no contact of the step holds, and after a
// steel ball hit a wall of fragments overlaps above 1 mm persisted for 15 steps, against 5 by
// translation.
//
// A speed setting (settings.h, isSpeedSetting: ten Gauss-Seidel sweeps, as Bullet and ODE's
// quickstep solve a pile) takes an unconverged impulse answer by choice, and under a pile's load
// that answer leaves about a thousand pairs of the 1000-box pile a few micrometres deep at every
// step; the eight passes over them, which never bring them within the micrometre tolerance under
// that load, were a sixth of the step. Such a setting projects only the points deeper than
// kProjectionDeepFactor times the tolerance (0.1 mm by default, a tenth of the acceptance bound
// for overlaps), each still all the way back to half the tolerance, as Box2D corrects only what
// is deeper than its linear slop. On the 1000-box pile (tumble-bench, 5 s at 1/240 s, 2026-11-28)
// the step took 16 % less (1.30 against 1.53 s per simulated second, one run each), its deepest
// overlap at the end stayed 1.0e-4 m, and 14 boxes left the bin, not 21.
//
// In the deep passes, under gravity, a pair stacked along gravity's line (its normal within 45
// degrees of it) is pushed apart by moving the upper body alone (if it can move: not a fixed or a
// sleeping body), the lower held as if fixed: the
// shock propagation of E. Guendelman, R. Bridson and R. Fedkiw ("Nonconvex rigid bodies with
// stacking", 2003), applied to the position passes. Pushed apart by their masses, a deep pair in a
// column sinks its lower body into the one below by half the depth, which the next pass pushes
// back up into it, and so on: a landing on the 1000-box pile set off six pushes in later passes
// for every pair deep at the start, the projection still pushing at its 32nd pass. Under a load
// resting on the ground the upper bodies end up lifted by the depth either way, so the rest state
// is the one the mass-weighted passes converge to. On the 1000-box pile (tumble-bench, 5 s at
// 1/240 s, ten sweeps, 2026-11-29): 284 000 pushes against 1.34 million, none past the 13th pass,
// and the step 6 % shorter (two interleaved runs each); the 100-piece pile's landings now end its
// steps 0.13 mm deep, not 0.63 mm (the passes no longer run out before they are out).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_islands.h"
#include "dynamics/world.h"

namespace tumble {

class DriftProjection {
 public:
  // Moves the bodies of `contacts` deeper than `tolerance_m` out, and updates every contact's
  // depth to the bodies' new positions (the solve goes on with these contacts). `deep_only`
  // (a speed setting): only the pairs with a point deeper than kProjectionDeepFactor times the
  // tolerance are pushed, in every pass (above). Returns the number of pushes.
  long project(World& world, std::vector<Contact>& contacts, double tolerance_m, bool deep_only = false);

 private:
  // Per body, for one projection: where it started, its displacement and its small turn (rad,
  // world axes), and its inverse inertia in world axes at the start.
  std::vector<Eigen::Vector3d> start_, moved_, turned_;
  std::vector<Eigen::Matrix3d> inverse_inertia_;
  std::vector<char> named_;              // per body: named by a contact of this projection
  // The push that moves a contact's two points apart by `depth` along its normal, with the least
  // mass-weighted motion: lambda = depth / K, K = w_a + w_b + (r_a x n) I_a^-1 (r_a x n) + (r_b x n) I_b^-1 (r_b x n);
  // a unit push turns A by -I_a^-1 (r_a x n) and B by I_b^-1 (r_b x n). Without turning, the push
  // translates the two bodies only (K = w_a + w_b).
  struct Response {
    double translating = 0, turning = 0;   // K
    double mass_a = 0, mass_b = 0;          // the inverse masses the push moves them by
    Eigen::Vector3d turn_a, turn_b;        // the turns of a unit push
    double largest_turn = 0;               // the larger of their norms
  };
  std::vector<double> pushed_;           // per contact: the push it has given in this pass (m kg)
  // Per contact, once its pair is first visited: [0, m) pushed by their masses, [m, 2m) as the deep
  // passes push it (a stacked pair's lower body held).
  std::vector<Response> responses_;
  std::vector<char> has_response_;
  std::vector<long> last_push_;          // per body: the number of the last push that moved it
  std::vector<long> found_shallow_;      // per pair: the number of pushes made when it was last found shallow
  BodyPairGroups grouped_;               // kept between steps: reused buffers
};

}  // namespace tumble
