// The one definition of a simulation's settings, with their units: filled by the scene loader
// (scene/scene_loader.cpp) and by the benchmark, read-only during a step (`const StepSettings&`).
// Below them, the tunings the solvers use, each named once with the reason for its value.
// Compare Jolt's PhysicsSettings and MuJoCo's mjOption.
#pragma once

#include <cstddef>

namespace tumble {

enum class Integrator { SemiImplicitEuler, Rk4 };

// How contacts are handled (one folder each under dynamics/, behind contact_model.h):
//   Baraff        event-driven: back-step to each first contact, Newton impulses, resting-force LCP
//   TimeStepping  Moreau / Stewart-Trinkle: one velocity-level impulse problem per step, solved by
//                 warm-started Gauss-Seidel; no back-stepping (fast, first order in dt)
//   Penalty       regularised: bodies overlap a little and a force law of the overlap and its rate
//                 pushes them apart; sub-steps as short as the stiffest contact needs
//   Auto          Baraff, or time stepping for a scene that starts with a crowd of free bodies
enum class ContactModel { Baraff, TimeStepping, Penalty, Auto };

// The regularised family's normal force laws (penalty/force_laws.h) and friction laws
// (penalty/friction_laws.h), as P. Flores, "Contact mechanics for dynamical systems: a comprehensive
// review", Multibody System Dynamics, 2022, presents them.
enum class NormalForceLaw { Hooke, KelvinVoigt, Hertz, HuntCrossley, LankaraniNikravesh, Flores };
enum class FrictionLaw { Coulomb, Threlfall, BengisuAkay, Ambrosio };

// Each law with its name in a scene file, once: the loader reads these names and `tumble check`,
// the refusal message and the tests print them.
template <typename Law> struct LawName {
  Law law;
  const char* name;
};
inline constexpr LawName<NormalForceLaw> kNormalForceLawNames[] = {
    {NormalForceLaw::Hooke, "hooke"},
    {NormalForceLaw::KelvinVoigt, "kelvin_voigt"},
    {NormalForceLaw::Hertz, "hertz"},
    {NormalForceLaw::HuntCrossley, "hunt_crossley"},
    {NormalForceLaw::LankaraniNikravesh, "lankarani_nikravesh"},
    {NormalForceLaw::Flores, "flores"}};
inline constexpr LawName<FrictionLaw> kFrictionLawNames[] = {{FrictionLaw::Coulomb, "coulomb"},
                                                             {FrictionLaw::Threlfall, "threlfall"},
                                                             {FrictionLaw::BengisuAkay, "bengisu_akay"},
                                                             {FrictionLaw::Ambrosio, "ambrosio"}};
template <typename Law, std::size_t N> constexpr const char* nameOf(Law law, const LawName<Law> (&names)[N]) {
  for (const LawName<Law>& n : names)
    if (n.law == law) return n.name;
  return "?";
}
inline constexpr const char* nameOf(NormalForceLaw law) { return nameOf(law, kNormalForceLawNames); }
inline constexpr const char* nameOf(FrictionLaw law) { return nameOf(law, kFrictionLawNames); }

struct PenaltySettings {
  NormalForceLaw law = NormalForceLaw::HuntCrossley;
  // N/m for the linear laws (hooke, kelvin_voigt), N/m^1.5 for the others; 0: from the bodies'
  // materials (Young's modulus, Poisson's ratio) and the contact's radius (penalty/contact_stiffness.h).
  double stiffness = 0;
  FrictionLaw friction_law = FrictionLaw::Coulomb;
  // m/s: Coulomb's ramp, Threlfall's threshold, Bengisu and Akay's peak, Ambrosio's upper speed v1.
  // Every regularised law lets a body creep at speeds of this order where Coulomb's would stick.
  double ramp_speed_m_s = 1e-3;
  double ambrosio_dead_speed_m_s = 1e-4;   // m/s: Ambrosio's v0, below which friction is off
  double static_friction_ratio = 1.2;      // Bengisu and Akay: mu_s / mu_d (the body's friction is mu_d)
  double stribeck_decay_s_m = 10;          // Bengisu and Akay's kappa, s/m: how fast mu falls to mu_d
  // Sub-steps per step at most. A contact that needs more (too stiff for its mass at this dt)
  // stops the run with the pair, its stiffness and the step it needs, never a silent blow-up.
  int max_substeps = 20000;
};

// What the coefficient of restitution e of a Baraff impact means (baraff/restitution_laws.h):
//   Newton   kinematic: the normal velocity after is -e times the one before
//   Poisson  kinetic: the normal impulse of restitution is e times that of compression
//   Stronge  energetic: restitution gives back e^2 of the work compression absorbed
// The three agree without friction, or where the slip keeps its direction through the impact.
enum class RestitutionLaw { Newton, Poisson, Stronge };

struct ContactSettings {
  double margin_m = 1e-3;           // m: pairs closer than this are reported by the narrow phase,
                                    // so contacts exist before they touch (cheap, coherent)
  double tolerance_m = 1e-6;        // m: |depth| within this is "touching"; a step that ends deeper
                                    // is bisected back to the first contact
  double resting_speed_m_s = 1e-3;  // m/s: a touching contact approaching slower than this rests;
                                    // faster it collides and gets Newton's impulse
  double sliding_speed_m_s = 1e-5;  // m/s: tangential speed above which friction is dynamic
  int max_bisections = 60;          // halvings of the step: 2^-60 of dt is far below rounding
  bool regula_falsi = false;        // bracket by linear interpolation (Illinois) instead of halving
  // Resting islands up to this many LCP rows (3 per contact) are solved exactly by pivoting
  // (cost ~ rows^3); larger ones (a pile) by Gauss-Seidel sweeps (cost ~ rows per sweep). 256
  // keeps a stack of 20 boxes (80 contacts, 240 rows) exact.
  int max_direct_rows = 256;
  RestitutionLaw restitution_law = RestitutionLaw::Newton;   // Baraff impacts: what e means
  // Time stepping: a pair of polyhedral pieces (or one and the ground) keeps its manifold between
  // steps and reuses it, its depths refreshed, while the pair has moved less than a tenth of the
  // margin (collision/kept_manifold.h). The Baraff and penalty models always run the narrow phase.
  bool reuse_manifolds = true;
};

struct SleepSettings {
  // Off unless asked: a scene file asks by default (scene.h, "sleep": true); steps set up by hand
  // (tests, the benchmark's own engines) say so themselves.
  bool enabled = false;
  // Box2D's thresholds (b2_linearSleepTolerance 1 cm/s, b2_angularSleepTolerance 2 deg/s,
  // b2_timeToSleep 0.5 s): a body this slow moves under 5 mm and turns under 1 deg before it
  // sleeps. Bullet's defaults (0.8 m/s, 1 rad/s, 2 s) are far coarser.
  double speed_m_s = 0.01;
  double spin_rad_s = 0.035;
  double after_s = 0.5;
};

// What a scene may ask of a run's accuracy ("simulation": {"target": {...}}): the automatic model
// chooses and tunes to meet it (auto/auto_model.h), and every run measures it (target_watch.h) and
// says at the end whether it was met. Zero: no target.
struct AccuracyTarget {
  double penetration_m = 0;   // m: the deepest any contact may be at the end of a step
  // The largest rise of the total energy (kinetic + gravitational + a compliant contact's spring)
  // above the lowest it reached, as a share of the energy in play: the fault check's measure
  // (energy_check.h). Dissipation is physics; a rise is error.
  double energy_drift = 0;
  bool any() const { return penetration_m > 0 || energy_drift > 0; }
};

struct StepSettings {
  double dt = 1.0 / 240;                          // s: fixed step, divides the frame interval
  Integrator integrator = Integrator::Rk4;        // how (x, q, P, L) advance over dt
  ContactSettings contact;                        // detection margin, tolerances, thresholds
  ContactModel model = ContactModel::Auto;        // auto (the default), event-driven, time stepping, penalty
  int time_stepping_sweeps = 200;                 // Gauss-Seidel sweeps per step at most (TimeStepping)
  PenaltySettings penalty;                        // force and friction laws (Penalty)
  SleepSettings sleep;                            // when quiet islands freeze (sleeping.h)
  AccuracyTarget target;                          // what auto must meet, and every run reports
  // Threads for detection and the islands' solves (dynamics/parallel_for.h). Not a scene setting:
  // it changes how fast a run goes, never a bit of what it computes (the CLI's --threads).
  int threads = 1;
};

// Tunings: fixed values the solvers use, not scene settings.
namespace tuning {

// Baraff model: sub-steps per step at most. Sub-steps end at first contacts, a few per step is
// normal; the cap only stops a contact that back-stepping cannot resolve from hanging the run
// (counted as a stuck sub-step).
inline constexpr int kMaxSubsteps = 256;
// Baraff model: a step is done when less than this share of dt remains.
inline constexpr double kStepRemainder = 1e-12;
// Baraff model: a first contact found earlier than this share of the sub-step is "at once": cutting
// there would stall the step in sub-steps of nothing (back_step.cpp).
inline constexpr double kImmediateContact = 1e-6;
// Drift projection passes (per step in the time-stepping model, per sub-step in the Baraff model);
// each reads the depths the earlier pushes left. One pass cannot keep up under a load (a column of
// boxes sank 6-8 cm in the pile) or in a chain (a block pushed out of the one above into the ground).
inline constexpr int kProjectionPasses = 8;
// Time-stepping drift projection: passes beyond kProjectionPasses, up to this many, push only the
// pairs with a point deeper than kProjectionDeepFactor times the contact tolerance (0.1 mm at the
// default tolerance, a tenth of the acceptance bound for overlaps), until no such pair is left. A
// settled pile's load leaves thousands of points micrometres deep after eight passes, where more
// passes over them buy nothing (every pass over them costs a sixth of the 1000-box pile's step);
// a landing in the 100-piece pile left 12 mm, which eight passes brought to 1.7 mm (a piece
// pushed out is pushed back by the ones it landed among) and the further passes below 0.1 mm
// (drift_projection.h; measured 2026-11-28).
inline constexpr int kProjectionMaxPasses = 32;
inline constexpr double kProjectionDeepFactor = 100;
// Time-stepping drift projection, deep passes: a pair whose normal is within 45 degrees of
// gravity's line is stacked, and its lower body is held while the upper is pushed out
// (drift_projection.h).
inline constexpr double kProjectionStackedCos = 0.7071;
// Time-stepping drift projection: sweeps over one pair's points within a pass at most (a face's
// four corners come out level within a few; drift_projection.h).
inline constexpr int kProjectionPairSweeps = 8;
// Time-stepping drift projection: the most one push may turn a body (rad); a push that would turn
// it further translates instead (drift_projection.h).
inline constexpr double kProjectionMaxTurn = 1e-3;
// Pivoting: passes over the friction bounds at most; the bounds settle to 1e-9 of the largest.
inline constexpr int kMaxFrictionPasses = 12;
inline constexpr double kFrictionTolerance = 1e-9;
// A pivoting answer that stopped short is used if its complementarity residual is within this
// share of the problem's scale (|b| + 1).
inline constexpr double kUsableComplementarity = 1e-6;
// Pivoting whose friction passes did not settle is solved again by complementary pivoting up to
// this many rows (6 variables per contact, dense: 6 ms for 96 rows, a stack of 8 cubes, in
// lcp_benchmark on the 2-core machine of 2026-11-29).
inline constexpr int kLemkeMaxRows = 96;
// Baraff model, dynamic friction on resting contacts: fixed-point passes on the normal forces at
// most, and the relative change at which they have settled.
inline constexpr int kMaxDynamicFrictionPasses = 8;
inline constexpr double kDynamicFrictionSettled = 1e-12;
// Velocity-level Gauss-Seidel: convergence, as a share of the largest velocity term, for islands
// kept at the Gauss-Seidel answer (a pile), and for small ones that are pivoted if it falls short
// (a flat landing solved only to 1e-6 leaves its four corners unequal: the cube spins at 3e-4 rad/s).
inline constexpr double kImpulseTolerance = 1e-6;
inline constexpr double kSmallIslandTolerance = 1e-12;
// Time-stepping model: sweeps before a small island is pivoted instead (pivoting a small island
// costs about as much as 30 sweeps over it).
inline constexpr int kSmallIslandSweeps = 30;
// Velocity-level Gauss-Seidel left unconverged at its cap: rounds of a subspace solve of the split it
// reached (active_set_step.h), each followed by this many sweeps that polish it and correct the
// split; each round costs about as much as its sweeps and iterations together.
inline constexpr int kActiveSetRounds = 4;
inline constexpr int kActiveSetSweeps = 20;
// A time-stepping sweep cap below this is a speed setting (a pile by ten sweeps, as Bullet and
// ODE's quickstep solve it) that takes an unconverged answer by choice: no subspace rounds, and a
// drift projection of the deep points only (drift_projection.h).
inline constexpr int kActiveSetMinSweeps = 100;
// Conjugate-gradient iterations per subspace step: about the length of the longest chain of bodies
// a load runs through (the 101-stone arch's half ring is 50).
inline constexpr int kActiveSetIterations = 100;
// Baraff model, a resting island too large to pivot and at rest: its velocity-level Gauss-Seidel
// may sweep up to this share of the square of its body count (at least the usual 200).
// Gauss-Seidel passes a change along a chain of N bodies by about one body a sweep and converges
// by about 1 - c / N^2 a sweep, so a long chain under load (the 101-stone arch) needs of the order
// of N^2 sweeps once; warm started from that answer, it then takes a few a step.
inline constexpr double kRestingChainSweeps = 0.5;

}  // namespace tuning

// A time-stepping speed setting (tuning::kActiveSetMinSweeps): the crowd setting of the automatic
// model (auto/auto_model.h) and the benchmark's fastest.
inline bool isSpeedSetting(const StepSettings& s) { return s.time_stepping_sweeps < tuning::kActiveSetMinSweeps; }

}  // namespace tumble
