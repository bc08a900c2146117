#include "dynamics/island_impulses.h"

#include "dynamics/active_set_step.h"
#include "dynamics/passive_impulses.h"
#include "dynamics/scratch_vector.h"
#include "dynamics/settings.h"

namespace tumble {

IslandImpulses solveIslandImpulses(const World& world, const ContactRows& rows, std::span<const Contact* const> island,
                                   const Eigen::VectorXd& b, const Eigen::VectorXd& start,
                                   const IslandImpulseSettings& settings, ContactSolveStats& stats) {
  IslandImpulses out;
  // A first guess of zero pushes nothing: the same sweeps as no first guess (row_gauss_seidel.cpp).
  out.p = start.size() == rows.size() ? start : Eigen::VectorXd::Zero(rows.size());
  out.converged = solveIslandImpulsesInPlace(world, rows, island, b, out.p, settings, stats);
  return out;
}

bool solveIslandImpulsesInPlace(const World& world, const ContactRows& rows, std::span<const Contact* const> island,
                                Eigen::Ref<const Eigen::VectorXd> b, Eigen::Ref<Eigen::VectorXd> p,
                                const IslandImpulseSettings& settings, ContactSolveStats& stats) {
  // Kept between calls on each thread: the limits, the round's answer and its subspace step.
  thread_local std::vector<RowLimit> limits;
  thread_local ScratchVector current_buffer, step_buffer;
  RowGaussSeidelSettings gs;
  gs.max_sweeps = settings.max_sweeps;
  gs.tolerance = settings.tolerance;
  pyramidLimits(rows, island, limits);
  RowGaussSeidelSweeps solved = sweepRowsGaussSeidel(world, rows.rows, b, limits, gs, p);
  ++stats.iterative_islands;
  stats.sweeps += solved.sweeps;
  // Unconverged at the cap (a long chain of bodies under load, active_set_step.h): solve the
  // equalities of the split Gauss-Seidel reached together, and let a few sweeps correct the split.
  // The answer kept is the one nearest a fixed point of Gauss-Seidel (whose last sweep changes the
  // rows least): the step's own merit ignores that friction bounds move with the normal forces,
  // and always taking the last round left a box of the time-stepping pile rocking. Rounds go on
  // until two in a row bring nothing nearer.
  if (settings.subspace_rounds && !solved.converged) {
    gs.max_sweeps = tuning::kActiveSetSweeps;
    auto current = current_buffer.view(p.size()), step = step_buffer.view(p.size());
    current = p;
    int misses = 0;
    for (int round = 0; round < tuning::kActiveSetRounds && !solved.converged && misses < 2; ++round) {
      ++stats.active_set_steps;
      activeSetStep(world, rows.rows, b, limits, current, step);
      current = step;
      const RowGaussSeidelSweeps round_sweeps = sweepRowsGaussSeidel(world, rows.rows, b, limits, gs, current);
      stats.sweeps += round_sweeps.sweeps;
      if (round_sweeps.converged || round_sweeps.last_change < solved.last_change) {
        solved = round_sweeps, misses = 0;
        p = current;
      } else {
        ++misses;
      }
    }
  }
  if (!solved.converged) {
    ++stats.unconverged_sweeps;
    // A warm start can leave an unconverged answer doing worse than no impulses: adding kinetic
    // energy (passive_impulses.h).
    if (keepPassive(world, rows.rows, b, limits, p, settings.gravity_dt) < 1) ++stats.passive_scaled;
  }
  return solved.converged;
}

}  // namespace tumble
