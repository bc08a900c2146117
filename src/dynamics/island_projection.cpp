#include "dynamics/island_projection.h"

#include <tuple>

#include "dynamics/contact_rows.h"

namespace tumble {

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
  const ContactRows& rows = lcp;
  auto entry = [&](int body) -> BodyDisplacement& {
    for (BodyDisplacement& d : out)
      if (d.body == body) return d;
    return out.emplace_back(BodyDisplacement{body});
  };
  // Pushes as impulses of a unit step: B moves by M^-1 J^T p along +dir, A along -dir.
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    const ContactRow& row = rows.rows[i];
    const double p = r.f[static_cast<Eigen::Index>(i)];
    if (p == 0) continue;
    const Eigen::Vector3d push = p * row.dir;
    for (const auto& [body, sign, arm] : {std::tuple{row.a, -1.0, row.ra}, std::tuple{row.b, 1.0, row.rb}}) {
      const RigidBody& rb = world.bodies[body];
      if (rb.is_static) continue;
      BodyDisplacement& d = entry(body);
      d.dx += sign * rb.inv_mass * push;
      d.dtheta += sign * (inverseInertiaWorld(rb) * arm.cross(push));
    }
  }
  return true;
}

}  // namespace tumble
