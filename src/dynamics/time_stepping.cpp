#include "dynamics/time_stepping.h"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/contact_lcp.h"
#include "dynamics/row_gauss_seidel.h"

namespace tumble {

void bodyReach(const World& world, const std::vector<double>& body_radius, double dt, std::vector<double>& reach) {
  reach.assign(world.bodies.size(), 0.0);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static) continue;
    reach[i] = (b.velocity().norm() + world.gravity.norm() * dt + b.angularVelocity().norm() * body_radius[i]) * dt;
  }
}

namespace {

// The rows of one island in buildContactLcp's layout (normal, then two tangents if mu > 0), with
// each row's velocity target and last step's impulse along it.
struct IslandRows {
  ContactLcp lcp;                // rows and normal_row only (A is formed only to pivot)
  Eigen::VectorXd target, start;
};

IslandRows rowsOf(const World& world, const std::vector<const Contact*>& island, const std::vector<double>& want,
                  const std::vector<const ImpulseRecord*>& last, const Contact* first) {
  IslandRows out;
  for (const Contact* c : island) {
    out.lcp.normal_row.push_back(static_cast<int>(out.lcp.rows.size()));
    out.lcp.rows.push_back(rowAlong(world, *c, c->normal));
    if (c->friction <= 0) continue;
    Eigen::Vector3d t1, t2;
    tangentsOf(c->normal, t1, t2);
    for (const Eigen::Vector3d& t : {t1, t2}) out.lcp.rows.push_back(rowAlong(world, *c, t));
  }
  const int n = static_cast<int>(out.lcp.rows.size());
  out.target = Eigen::VectorXd::Zero(n);
  out.start = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < island.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(island[k] - first);
    const int r0 = out.lcp.normal_row[k];
    const int r_end = k + 1 < island.size() ? out.lcp.normal_row[k + 1] : n;
    out.target[r0] = want[i];
    if (!last[i]) continue;
    for (int r = r0; r < r_end; ++r) out.start[r] = last[i]->impulse.dot(out.lcp.rows[r].dir);
    out.start[r0] = std::max(0.0, out.start[r0]);
  }
  return out;
}

Eigen::VectorXd solveByGaussSeidel(const World& world, const IslandRows& rows, const std::vector<const Contact*>& island,
                                   const Eigen::VectorXd& b, int max_sweeps, double tolerance,
                                   ContactSolveStats& stats, bool& converged) {
  const int n = static_cast<int>(rows.lcp.rows.size());
  std::vector<RowLimit> limits(n);
  for (std::size_t k = 0; k < island.size(); ++k) {
    const int r0 = rows.lcp.normal_row[k];
    const int r_end = k + 1 < island.size() ? rows.lcp.normal_row[k + 1] : n;
    for (int r = r0 + 1; r < r_end; ++r) limits[r] = {RowLimit::Static, r0, island[k]->friction, 0};
  }
  RowGaussSeidelSettings gs;
  gs.max_sweeps = max_sweeps;
  gs.tolerance = tolerance;
  RowGaussSeidelResult solved = solveRowsGaussSeidel(world, rows.lcp.rows, b, limits, gs, rows.start);
  ++stats.iterative_islands;
  stats.sweeps += solved.sweeps;
  if (!solved.converged) ++stats.unconverged_sweeps;
  converged = solved.converged;
  return solved.f;
}

}  // namespace

void TimeStepper::applyContactImpulses(World& world, const std::vector<Contact>& contacts,
                                       const std::vector<double>& approach, const StepSettings& settings,
                                       double min_bounce_speed, ContactSolveStats& stats) {
  const double dt = settings.dt;
  const std::size_t m = contacts.size();
  std::vector<const ImpulseRecord*> last(m);
  std::vector<double> want(m), owed(m, 0);   // normal velocity target; landing speed carried in
  std::vector<const Contact*> all(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Contact& c = contacts[i];
    all[i] = &c;
    last[i] = memory_.find(world, c, ImpulseMemory::kMatchRadius);
    owed[i] = last[i] ? last[i]->landing_speed : 0;
    const double gap = -c.depth;
    want[i] = -std::max(gap, 0.0) / dt;
    const double u = std::max(approach[i], owed[i]);
    if (gap <= settings.contact.tolerance_m && u > min_bounce_speed) want[i] = std::max(want[i], c.restitution * u);
  }
  stats.resting += static_cast<long>(m);

  std::vector<Eigen::Vector3d> impulse(m, Eigen::Vector3d::Zero());   // on B, world axes
  std::vector<double> normal_impulse(m, 0);
  // Each body's velocity once (the rows need it twice each; computing omega costs a rotation).
  velocity_.resize(world.bodies.size());
  spin_.resize(world.bodies.size());
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    const RigidBody& body = world.bodies[k];
    velocity_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.velocity();
    spin_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.angularVelocity();
  }
  auto rowVelocityNow = [&](const ContactRow& r) {
    return r.dir.dot(velocity_[r.b] + spin_[r.b].cross(r.rb) - velocity_[r.a] - spin_[r.a].cross(r.ra));
  };
  // Islands are solved one by one even by Gauss-Seidel: each then sweeps until it has itself
  // converged (one solve over all of them would stop quiet islands at the busiest one's tolerance).
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, all)) {
    // Gauss-Seidel first, warm-started: most islands (a pair of boxes meeting, a stack resting
    // as it did last step) converge within a few sweeps. One that does not (a heavy box on a light
    // one: Gauss-Seidel converges at a rate set by the mass ratio; a tall stack) is solved exactly
    // by pivoting if it is small enough, and keeps the Gauss-Seidel answer otherwise (a pile).
    IslandRows rows = rowsOf(world, island, want, last, contacts.data());
    const int n = static_cast<int>(rows.lcp.rows.size());
    Eigen::VectorXd b(n);
    for (int r = 0; r < n; ++r) b[r] = rowVelocityNow(rows.lcp.rows[r]) - rows.target[r];
    // An island that may be pivoted must converge to near rounding (a flat landing solved only to
    // 1e-6 leaves its four corners unequal, and the cube spins at 3e-4 rad/s).
    const bool small = 3 * island.size() <= static_cast<std::size_t>(settings.contact.max_direct_rows);
    bool converged = false;
    // Pivoting a small island costs about as much as 30 sweeps over it: more are not worth trying.
    const int sweeps = small ? std::min(settings.time_stepping_sweeps, 30) : settings.time_stepping_sweeps;
    Eigen::VectorXd f = solveByGaussSeidel(world, rows, island, b, sweeps, small ? 1e-12 : 1e-6, stats, converged);
    if (!converged && small) {
      ContactLcp exact = buildContactLcp(world, island, std::vector<char>(island.size(), 1));   // same rows
      exact.problem.b = b;
      lcp::LcpResult r = solveContactLcp(exact.problem, stats);
      const bool usable = r.status == lcp::LcpStatus::Solved ||
                          (r.f.allFinite() && r.residual.complementarity <= 1e-6 * (b.lpNorm<Eigen::Infinity>() + 1));
      if (usable) f = r.f;
      else ++stats.iterative_fallbacks;
    }
    applyAlongRows(world, rows.lcp.rows, f);
    for (std::size_t k = 0; k < island.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(island[k] - contacts.data());
      const int r0 = rows.lcp.normal_row[k];
      const int r_end = k + 1 < island.size() ? rows.lcp.normal_row[k + 1] : n;
      for (int r = r0; r < r_end; ++r) impulse[i] += f[r] * rows.lcp.rows[r].dir;
      normal_impulse[i] = f[r0];
    }
  }

  std::vector<ImpulseRecord> records(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Contact& c = contacts[i];
    ImpulseRecord& rec = records[i];
    rec.a = c.a;
    rec.b = c.b;
    rec.local = ImpulseMemory::localPoint(world, c);
    rec.impulse = impulse[i];
    // A landing the margin closed this step (pushed, not yet touching) is owed its bounce.
    const bool landing = -c.depth > settings.contact.tolerance_m && normal_impulse[i] > 0;
    rec.landing_speed = landing ? std::max(approach[i], owed[i]) : 0;
  }
  memory_.replace(std::move(records));
}

}  // namespace tumble
