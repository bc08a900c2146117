#include "dynamics/island_projection.h"

#include <tuple>

#include "dynamics/contact_rows.h"
#include "dynamics/island_impulses.h"

namespace tumble {

namespace {

// The displacement M^-1 J^T p of the moving bodies, pushes read as impulses of a unit step: B
// moves along +dir, A along -dir.
void displacementsOf(const World& world, const ContactRows& rows, const Eigen::VectorXd& p,
                     std::vector<BodyDisplacement>& out) {
  out.clear();
  auto entry = [&](int body) -> BodyDisplacement& {
    for (BodyDisplacement& d : out)
      if (d.body == body) return d;
    return out.emplace_back(BodyDisplacement{body});
  };
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    const ContactRow& row = rows.rows[i];
    const double f = p[static_cast<Eigen::Index>(i)];
    if (f == 0) continue;
    const Eigen::Vector3d push = f * row.dir;
    for (const auto& [body, sign, arm] : {std::tuple{row.a, -1.0, row.ra}, std::tuple{row.b, 1.0, row.rb}}) {
      const RigidBody& rb = world.bodies[body];
      if (rb.is_static) continue;
      BodyDisplacement& d = entry(body);
      d.dx += sign * rb.inv_mass * push;
      d.dtheta += sign * (inverseInertiaWorld(rb) * arm.cross(push));
    }
  }
}

}  // namespace

bool islandProjection(const World& world, std::span<const Contact* const> island, double tol,
                      std::vector<BodyDisplacement>& out, ContactSolveStats& stats) {
  out.clear();
  ContactLcp lcp;
  buildContactLcp(world, island, lcp);
  lcp::LcpProblem& problem = lcp.problem;
  problem.b.setZero();   // friction rows: no slide
  for (std::size_t k = 0; k < island.size(); ++k)
    problem.b[lcp.normal_row[k]] = 0.5 * tol - island[k]->depth;
  const lcp::LcpResult r = solveContactLcp(problem, stats);
  if (!usableLcpAnswer(r, problem)) return false;
  displacementsOf(world, lcp, r.f, out);
  return true;
}

bool islandProjectionBySweeps(const World& world, std::span<const Contact* const> island, double tol,
                              std::vector<BodyDisplacement>& out, ContactSolveStats& stats) {
  ContactRows rows;
  buildContactRows(world, island, rows);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.rows.size()));
  for (std::size_t k = 0; k < island.size(); ++k) b[rows.normal_row[k]] = 0.5 * tol - island[k]->depth;
  // From no push. Stopped at their cap the sweeps are part of the way: on a long chain a pass can
  // leave a joint deeper than it found it (a push passed along only partly), and the next pass,
  // on the contacts this one leaves, goes on from there.
  Eigen::VectorXd p = Eigen::VectorXd::Zero(b.size());
  solveIslandImpulsesInPlace(world, rows, island, b, p, IslandImpulseSettings{}, stats);
  if (!p.allFinite()) return false;
  displacementsOf(world, rows, p, out);
  return true;
}

}  // namespace tumble
