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
  gs.max_sweeps = tuning::kActiveSetSweeps;
  // A round is kept only if it leaves the answer nearer a fixed point of Gauss-Seidel (its last
  // sweep changes the rows less): the step's own merit ignores that friction bounds move with the
  // normal forces, and a step that lowered it could still leave a pile's box rocking.
  for (int round = 0; round < tuning::kActiveSetRounds && !solved.converged; ++round) {
    ++stats.active_set_steps;
    RowGaussSeidelResult next =
        solveRowsGaussSeidel(world, rows.rows, b, limits, gs, activeSetStep(world, rows.rows, b, limits, solved.f));
    stats.sweeps += next.sweeps;
    if (!next.converged && !(next.last_change < solved.last_change)) break;
    solved = std::move(next);
  }
  if (!solved.converged) ++stats.unconverged_sweeps;
  return {std::move(solved.f), solved.converged};
}

}  // namespace tumble
