// Thin plates and tall cribs (docs/hard-cases.md), written by tools/make-thin-stacks: a two-level
// house of playing cards (0.5 mm, 2 g, tents at 65 degrees, mu = 0.5; scenes/hard/card_house.json),
// its smallest part, one tent on a card lying loose on the ground (tent_on_card.json), and a crib
// tower of 102 Kapla planks, 17 levels of 6 on edge (crib102.json, dt = 1/100 s). Statics says all
// three stand: a tent's feet need F / N = 1 / (2 tan 65) = 0.233 < mu, and the crib carries its
// weight straight down through square patches. Criteria, after every step:
//   - no piece's centre moving more than 1 mm from where it started (the pieces start 0.01 mm
//     apart, so settling moves the highest plank 0.17 mm), over 2 s for the cards and 60 s for
//     the crib;
//   - no pair of bodies overlapping by more than 1 mm (exact separating-axis depth), the
//     acceptance bound for overlaps;
//   - no run-time fault (counted, so that the run goes on and the other figures are measured).
// Both contact models. The largest energy rise above the lowest energy reached, relative to the
// scene's energy scale, is printed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>

#include "../dynamics/contact_scene_runner.h"

using namespace tumble;

namespace {

struct StackOutcome {
  double overlap = 0;        // m: deepest, at the steps measured
  double moved = 0;          // m: the largest distance of any centre from its start
  std::string moved_most;
  double energy_rise = 0;    // share of the energy scale (test::EnergyRise)
  double wall_per_s = 0;     // s of wall time per simulated second
  long faults = 0;
  std::string first_fault;
};

StackOutcome standStack(const std::string& name, double seconds, ContactModel model, int overlap_every = 1) {
  StackOutcome out;
  std::vector<Eigen::Vector3d> start;
  test::EnergyRise energy;
  const auto began = std::chrono::steady_clock::now();
  auto run = test::runScene(
      "hard/" + name, seconds,
      [&](const World& w) {
        if (start.empty())
          for (const RigidBody& b : w.bodies) start.push_back(b.x);
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
          const RigidBody& b = w.bodies[i];
          if (b.is_static) continue;
          const double d = (b.x - start[i]).norm();
          if (d > out.moved) out.moved = d, out.moved_most = b.name;
        }
        energy.add(w);
      },
      overlap_every, [&](Scene& s) { s.simulation.step.model = model; }, true);
  out.wall_per_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() / seconds;
  out.overlap = run.max_penetration;
  out.faults = run.faults;
  out.first_fault = run.first_fault;
  out.energy_rise = energy.largest();
  return out;
}

void checkStands(const StackOutcome& out) {
  INFO("largest move " << out.moved << " m (" << out.moved_most << "), deepest overlap " << out.overlap
                       << " m, energy rise " << out.energy_rise << " of the scale, " << out.wall_per_s
                       << " s wall per s, " << out.faults << " steps at fault; the first: " << out.first_fault);
  CHECK(out.faults == 0);
  CHECK(out.overlap < 1e-3);
  CHECK(out.moved < 1e-3);
}

}  // namespace

TEST_CASE("one tent on a loose card, time stepping: stands 2 s, no piece moves 1 mm, no fault", "[hard][thin][time_stepping]") {
  checkStands(standStack("tent_on_card", 2, ContactModel::TimeStepping));
}

TEST_CASE("house of cards, time stepping: stands 2 s, no piece moves 1 mm, no fault", "[hard][thin][time_stepping]") {
  checkStands(standStack("card_house", 2, ContactModel::TimeStepping));
}

// The tent stands on its loose card with the Baraff model: 2.9e-11 m after the first step,
// overlaps of 8.6e-8 m, no fault (2026-11-25). It fell (8.1 cm, overlap faults from 0.61 s) for two
// reasons. The ridge, two parallel edges, was held at one end only: clipped from one card's face it
// kept whichever end rounding left (collision/clip.cpp, parallelEdgeContact), and apart it was
// one closest point. And the landing's impulses were resolved pair by pair, feet first, which
// spun the two cards unequally; a plastic impact is now solved at once (impulse_propagation.h).
TEST_CASE("one tent on a loose card, Baraff: stands 2 s, no piece moves 1 mm, no fault", "[hard][thin]") {
  checkStands(standStack("tent_on_card", 2, ContactModel::Baraff));
}

// The house stands with the Baraff model: 0.22 mm, overlaps of 1.5e-6 m, no fault (2026-11-25).
// Before, the top tent's cards pressed into the card laid across the lower tents, overlap faults
// on 463 steps: the drift correction ran once, on the contacts of the sub-step's start after a
// back-step (baraff/baraff_model.cpp). (It fell, 11.4 cm, until opposite faces in contact took the
// larger face's normal.)
TEST_CASE("house of cards, Baraff: stands 2 s, no piece moves 1 mm, no fault", "[hard][thin]") {
  checkStands(standStack("card_house", 2, ContactModel::Baraff));
}

// The crib's 102 bodies make the exact overlap of every pair costly: measured every 10th step and
// at the end. The suite runs 10 s of the criterion's 60 (about 2.6 s of wall time per simulated
// second without sleeping): the planks settle by 0.72 mm at most and are at rest within about
// 0.8 s, overlaps of 0.027 mm, no fault (2026-11-27). Run for the full 60 s without sleeping by
// `tumble simulate` it stays at rest, no fault, below 5e-7 m/s from 20 s. Before the drift
// projection pushed pairs apart at their points, turning as well as lifting
// (time_stepping/drift_projection.h), it was a known failure on a 1 s horizon: Gauss-Seidel stops
// at its cap on every step here too, and each translation lifted a plank pitched onto one
// crossing by that corner's depth and left it pitched; the top planks rocked and slid at up to
// 5 cm/s, 2.3 mm by 1 s, and the lifts tripped the energy-gain check from 0.75 s.
TEST_CASE("crib of 102 planks, time stepping: stands, no piece moves 1 mm, no fault (10 s horizon)",
          "[hard][thin][crib][time_stepping]") {
  checkStands(standStack("crib102", 10, ContactModel::TimeStepping, 10));
}

// The Baraff model stands the crib over the suite's 10 s, as time stepping does: no plank moves
// more than 2.6e-6 m, overlaps of 9.7e-7 m, no fault, about 1.2 s of wall time per simulated
// second; run for the criterion's 60 s by `tumble simulate --no-sleep` no plank moves more than
// 0.17 mm, no fault, 1.2 s of wall time per simulated second (2026-11-28).
// Before, planks moved 7.9 mm and overlapped 7.7 mm within 0.1 s, at 131 s of wall time per
// simulated second: the drift correction projected the crib's islands, too large to pivot, pair
// by pair, and the pairs pushed each other back; they are now projected whole by sweeps
// (island_projection.h).
TEST_CASE("crib of 102 planks, Baraff: stands, no piece moves 1 mm, no fault (10 s horizon)", "[hard][thin][crib]") {
  checkStands(standStack("crib102", 10, ContactModel::Baraff, 10));
}

// The class's energy criterion: a passive scene's total energy may not rise above the lowest it has
// reached by more than 1e-6 of its energy scale (the largest kinetic energy plus the range of
// potential energy). Where pieces settle into overlaps, the position correction lifts them back
// out and returns potential energy the settling took (docs/known-limits.md, "Energy regained after
// settling"); the run-time check allows 1e-3 of the scale plus a 0.1 mm lift of every body. Over
// the cards' 2 s.
void checkNoEnergyGain(const StackOutcome& out) {
  INFO("largest energy rise " << out.energy_rise << " of the scale");
  CHECK(out.energy_rise < test::kEnergyRiseBound);
}

// Time stepping keeps it: no rise at all over 2 s (2026-11-29; 1.5e-3 of the scale on 2026-11-27).
// Not asserted for the Baraff model: with nothing moving after the landing its scale is rounding
// (below 1e-12 J), and so is the rise, which comes out as the whole of it.
TEST_CASE("house of cards, time stepping: energy never rises above its lowest by 1e-6 of the scale",
          "[hard][thin][energy][time_stepping]") {
  checkNoEnergyGain(standStack("card_house", 2, ContactModel::TimeStepping));
}
