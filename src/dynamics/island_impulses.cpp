#include "dynamics/island_impulses.h"

#include "dynamics/active_set_step.h"
#include "dynamics/settings.h"

namespace tumble {

IslandImpulses solveIslandImpulses(const World& world, const ContactRows& rows,
                                   const std::vector<const Contact*>& island, const Eigen::VectorXd& b,
                                   const Eigen::VectorXd& start, const IslandImpulseSettings& settings,
                                   ContactSolveStats& stats) {
  RowGaussSeidelSettings gs;
  gs.max_sweeps = settings.max_sweeps;
  gs.tolerance = settings.tolerance;
  const std::vector<RowLimit> limits = pyramidLimits(rows, island);
  RowGaussSeidelResult solved = solveRowsGaussSeidel(world, rows.rows, b, limits, gs, start);
  ++stats.iterative_islands;
  stats.sweeps += solved.sweeps;
  // Unconverged at the cap (a long chain of bodies under load, active_set_step.h): solve the
  // equalities of the split Gauss-Seidel reached together, and let a few sweeps correct the split.
  // The answer kept is the one nearest a fixed point of Gauss-Seidel (whose last sweep changes the
  // rows least): the step's own merit ignores that friction bounds move with the normal forces,
  // and always taking the last round left a box of the time-stepping pile rocking. Rounds go on
  // until two in a row bring nothing nearer.
  if (settings.subspace_rounds) {
    gs.max_sweeps = tuning::kActiveSetSweeps;
    RowGaussSeidelResult current = solved;
    int misses = 0;
    for (int round = 0; round < tuning::kActiveSetRounds && !solved.converged && misses < 2; ++round) {
      ++stats.active_set_steps;
      current = solveRowsGaussSeidel(world, rows.rows, b, limits, gs, activeSetStep(world, rows.rows, b, limits, current.f));
      stats.sweeps += current.sweeps;
      if (current.converged || current.last_change < solved.last_change) solved = current, misses = 0;
      else ++misses;
    }
  }
  if (!solved.converged) ++stats.unconverged_sweeps;
  return {std::move(solved.f), solved.converged};
}

}  // namespace tumble
