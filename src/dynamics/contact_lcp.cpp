#include "dynamics/contact_lcp.h"

#include <limits>

#include "dynamics/contact_solver.h"
#include "dynamics/lcp/dantzig_solver.h"

namespace tumble {

ContactLcp buildContactLcp(const World& world, const std::vector<const Contact*>& set,
                           const std::vector<char>& friction) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ContactLcp out;
  std::vector<int> friction_of;
  std::vector<double> mu;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const Contact* c = set[i];
    out.normal_row.push_back(static_cast<int>(out.rows.size()));
    out.rows.push_back(rowAlong(world, *c, c->normal));
    friction_of.push_back(-1);
    mu.push_back(0);
    if (friction[i] && c->friction > 0) {
      Eigen::Vector3d t1, t2;
      tangentsOf(c->normal, t1, t2);
      for (const Eigen::Vector3d& t : {t1, t2}) {
        out.rows.push_back(rowAlong(world, *c, t));
        friction_of.push_back(out.normal_row.back());
        mu.push_back(c->friction);
      }
    }
  }
  const int n = static_cast<int>(out.rows.size());
  out.problem.A = delassus(world, out.rows);
  out.problem.b = Eigen::VectorXd::Zero(n);
  out.problem.lo = Eigen::VectorXd::Zero(n);
  out.problem.hi = Eigen::VectorXd::Constant(n, kInf);
  out.problem.friction_of = friction_of;
  out.problem.mu = Eigen::Map<Eigen::VectorXd>(mu.data(), n);
  return out;
}

lcp::LcpResult solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats) {
  // Redundant contacts (four corners of a face) leave the split of the normal force between them
  // free, so the friction bounds +-mu f_n need not settle to the last bit between passes: settle to
  // 1e-9 of the largest bound (far below any force that moves a body measurably).
  lcp::DantzigSettings settings;
  settings.friction_tolerance = 1e-9;
  settings.max_friction_passes = 12;
  lcp::LcpResult r = lcp::solveDantzig(p, settings);
  stats.pivots += r.iterations;
  if (r.status != lcp::LcpStatus::Solved) ++stats.failures;
  return r;
}

double normalVelocity(const World& world, const Contact& c) {
  return rowVelocity(world, rowAlong(world, c, c.normal));
}

}  // namespace tumble
