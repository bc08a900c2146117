#include "dynamics/island_impulses.h"

namespace tumble {

IslandImpulses solveIslandImpulses(const World& world, const ContactRows& rows,
                                   const std::vector<const Contact*>& island, const Eigen::VectorXd& b,
                                   const Eigen::VectorXd& start, const IslandImpulseSettings& settings,
                                   ContactSolveStats& stats) {
  RowGaussSeidelSettings gs;
  gs.max_sweeps = settings.max_sweeps;
  gs.tolerance = settings.tolerance;
  RowGaussSeidelResult solved = solveRowsGaussSeidel(world, rows.rows, b, pyramidLimits(rows, island), gs, start);
  ++stats.iterative_islands;
  stats.sweeps += solved.sweeps;
  if (!solved.converged) ++stats.unconverged_sweeps;
  return {std::move(solved.f), solved.converged};
}

}  // namespace tumble
