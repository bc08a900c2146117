// Masonry arches (docs/hard-cases.md): semicircular arches of 25 and 101 convex voussoirs standing
// on the ground by friction alone (scenes/hard/arch25.json, arch101.json, written by
// tools/make-arch; mu = 0.5, dt = 1/100 s, clear span 18 m, joints opened by 0.1 mm). The ring is
// thick enough for a thrust line and needs shear / normal 0.31 at its worst joint (the feet), so
// by J. Heyman, "The Stone Skeleton" (1995), it stands: once the gaps have closed no stone may
// move. Criteria, after every step:
//   - no run-time fault (the simulator's fault check: a body moved farther than its speeds allow,
//     energy risen above the lowest reached, a deep overlap; counted here, the run goes on so
//     that the other figures are measured too);
//   - no pair of bodies overlapping by more than 1 mm (exact separating-axis depth), the
//     acceptance bound for overlaps;
//   - no stone's centre moving more than 1e-3 of the span (18 mm) from where it was once the gaps
//     had closed (0.1 s: a 0.1 mm gap closes under gravity in 5 ms, and the ring then carries its
//     weight).
// Both contact models. The largest energy rise above the lowest energy reached, relative to the
// scene's energy scale (largest kinetic energy plus the range of potential energy), is printed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "../dynamics/contact_scene_runner.h"
#include "hard_run.h"

using namespace tumble;

namespace {

constexpr double kSpan = 18;          // m: clear span, twice the intrados radius (tools/make-arch)
constexpr double kSettled = 0.1;      // s: the gaps have closed

struct ArchOutcome {
  double overlap = 0;                 // m: deepest, any step
  double centre_motion = 0;           // m: largest of any stone after kSettled
  double energy_rise = 0;             // share of the energy scale (test::EnergyRise)
  double wall_per_s = 0;              // s of wall time per simulated second
  long faults = 0;                    // steps the run-time fault check found at fault
  std::string first_fault;
};

ArchOutcome standArch(const std::string& name, double seconds, ContactModel model) {
  ArchOutcome out;
  std::vector<Eigen::Vector3d> settled;
  test::EnergyRise energy;
  const auto start = std::chrono::steady_clock::now();
  auto run = test::runScene(
      name, seconds,
      [&](const World& w) {
        if (w.time >= kSettled - 1e-9 && settled.empty())
          for (const RigidBody& b : w.bodies) settled.push_back(b.x);
        if (!settled.empty())
          for (std::size_t i = 0; i < w.bodies.size(); ++i)
            out.centre_motion = std::max(out.centre_motion, (w.bodies[i].x - settled[i]).norm());
        energy.add(w);
      },
      1, [&](Scene& s) { s.simulation.step.model = model; }, true);
  out.wall_per_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / seconds;
  out.overlap = run.max_penetration;
  out.faults = run.faults;
  out.first_fault = run.first_fault;
  out.energy_rise = energy.largest();
  return out;
}

void checkArch(const ArchOutcome& out) {
  INFO("deepest overlap " << out.overlap << " m, centre motion after " << kSettled << " s " << out.centre_motion
                          << " m (" << out.centre_motion / kSpan << " of the span), energy rise "
                          << out.energy_rise << " of the scale, " << out.wall_per_s << " s wall per s, "
                          << out.faults << " steps at fault; the first: " << out.first_fault);
  CHECK(out.faults == 0);
  CHECK(out.overlap < 1e-3);
  CHECK(out.centre_motion < 1e-3 * kSpan);
}

}  // namespace

// The time-stepping model stands both arches for the full 20 s (about 1 and 30 s of wall time on
// the 2-core machine; 25 stones: 0.52 mm of motion, overlaps of 0.060 mm, 2026-11-24). Before the
// subspace steps of active_set_step.h the 25-stone arch sagged 0.35 m in 20 s and the 101-stone
// one sank 0.2 m in 5 s.
TEST_CASE("arch of 25 voussoirs, time stepping: stands 20 s, no overlap above 1 mm, no fault", "[hard][arch][time_stepping]") {
  checkArch(standArch("hard/arch25", 20, ContactModel::TimeStepping));
}

// The 101-stone arch stands with no fault (2026-11-29): centre motion 4.1 mm, 2.3e-4 of the span;
// overlap 0.46 mm; largest energy rise 0.035 of the scale; 0.8-1.3 s of wall time per simulated
// second. Narrowly: until the same day the drift projection, lifting the ring out of the overlaps
// Gauss-Seidel left as the joints closed, raised the total energy above the lowest it had reached
// by 314 J at t = 0.67 s where the fault check allows 312 J, and on 567 of the 2000 steps (0.038
// of the scale). What changed is the settling's path: the time-stepping model now solves a step's
// impacts before gravity's impulse and the load (time_stepping/contact_impulses.h), and six of the
// ring's 2000 steps have one (joints closing faster than the resting speed), five by t = 0.31 s.
TEST_CASE("arch of 101 voussoirs, time stepping: stands 20 s, no overlap above 1 mm, no fault",
          "[hard][arch][time_stepping]") {
  checkArch(standArch("hard/arch101", 20, ContactModel::TimeStepping));
}

// The Baraff model stands the 25-stone arch for the full 20 s: 0.21 mm of motion, overlaps of
// 0.11 mm, 0.17 s of wall time per simulated second (2026-11-24). It fell by 54 mm in 2 s before
// the rocking block's fixes (a lift-off settles only when the step cannot follow it; resting
// normal rows stop their drift: baraff/impulse_propagation.h, baraff/resting_forces.cpp).
TEST_CASE("arch of 25 voussoirs, Baraff: stands 20 s, no overlap above 1 mm, no fault", "[hard][arch]") {
  checkArch(standArch("hard/arch25", 20, ContactModel::Baraff));
}

// The Baraff model on 101 stones, on a 0.3 s horizon, past the settling. Within it the ring
// holds: centre motion 1.3 mm after 0.1 s, overlaps of 0.03 mm (2026-11-25); before, it fell
// 0.18 m in 0.3 s with overlaps of 8.7 mm (the drift correction ran once, on the contacts of the
// sub-step's start after a back-step, so a stone pushed out of one neighbour stayed in the other:
// baraff/baraff_model.cpp).
TEST_CASE("arch of 101 voussoirs, Baraff: stands, no overlap above 1 mm, no fault (0.3 s horizon)", "[hard][arch]") {
  checkArch(standArch("hard/arch101", 0.3, ContactModel::Baraff));
}

// The Baraff model stands the 101-stone arch for the criterion's 20 s: no centre moving more than
// 0.28 mm after 0.1 s, overlaps of 1.0e-6 m, no fault, about 1 s of wall time per simulated second
// here with every step's exact overlaps (2026-11-28). Two changes that day brought it there. The
// drift correction pushed the ring's joints pair by pair: a closed chain between two feet, where a
// push that parts one joint closes its neighbours, so eight passes a step left its 3 um joints as
// deep as they found them and lifted the ring a little each time (energy-gain faults on 1432 of
// 2000 steps from 5.69 s); the island is now projected whole by sweeps (island_projection.h).
// Then the ring crept down, 6.3 mm in 20 s, its resting solve stopping at 200 sweeps on every
// step; an island at rest may now sweep up to half the square of its body count
// (baraff/resting_forces.cpp).
TEST_CASE("arch of 101 voussoirs, Baraff: stands 20 s, no overlap above 1 mm, no fault", "[hard][arch]") {
  checkArch(standArch("hard/arch101", 20, ContactModel::Baraff));
}

// The Baraff model's resting solve on the 101-stone arch once it has settled: the ring is one
// resting island of about 400 contacts in a chain between the feet, at rest, and its solve must
// converge on every step. Stopped at 200 sweeps it did not, on any step, and the unbalanced
// impulses it left let the ring creep down 6.3 mm in 20 s (2026-11-28); an island at rest may now
// sweep up to half the square of its body count (baraff/resting_forces.cpp), which the first
// steps after the settling use, and then a few sweeps a step hold it. The settling's last capped
// solve comes at about 2.2 s (1338 in all, 2026-11-29): every solve after 2.5 s must converge.
TEST_CASE("arch of 101 voussoirs, Baraff: once settled, every resting solve converges", "[hard][arch]") {
  Scene scene = hard::loadHardScene("arch101");
  scene.simulation.step.model = ContactModel::Baraff;
  scene.simulation.step.sleep.enabled = false;
  const long settled = hard::simulate(scene, 2.5).counters.contacts.unconverged_sweeps;
  const long later = hard::simulate(scene, 4).counters.contacts.unconverged_sweeps;
  INFO("solves stopped at their cap: " << settled << " in the first 2.5 s, " << later - settled << " from 2.5 s to 4 s");
  CHECK(later - settled == 0);
}

// The class's energy criterion: a passive scene's total energy may not rise above the lowest it has
// reached by more than 1e-6 of its energy scale (the largest kinetic energy plus the range of
// potential energy). The ring settles into overlaps as its 0.1 mm joints close, and the position
// correction lifts it back out over the next steps, returning potential energy the settling took
// (docs/known-limits.md, "Energy regained after settling"); the run-time check allows 1e-3 of the
// scale plus a 0.1 mm lift of every stone. Known failures, with the figure reached over 2 s
// (2026-11-29; time stepping 0.072 before its impacts were solved ahead of the load).
TEST_CASE("arch of 25 voussoirs, time stepping: energy never rises above its lowest by 1e-6 of the scale (known failure: 0.035)",
          "[hard][arch][energy][time_stepping][!shouldfail]") {
  const ArchOutcome out = standArch("hard/arch25", 2, ContactModel::TimeStepping);
  INFO("largest energy rise " << out.energy_rise << " of the scale");
  CHECK(out.energy_rise < test::kEnergyRiseBound);
}

TEST_CASE("arch of 25 voussoirs, Baraff: energy never rises above its lowest by 1e-6 of the scale (known failure: 0.0031)",
          "[hard][arch][energy][!shouldfail]") {
  const ArchOutcome out = standArch("hard/arch25", 2, ContactModel::Baraff);
  INFO("largest energy rise " << out.energy_rise << " of the scale");
  CHECK(out.energy_rise < test::kEnergyRiseBound);
}
