#include "dynamics/active_set_step.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

#include "dynamics/settings.h"

namespace tumble {
namespace {

// A row's part of J on one body: the sign of the side, and its linear and angular parts.
struct Side {
  int row = 0;
  Eigen::Vector3d lin, ang;   // J's parts (dir, r x dir), signed
};

}  // namespace

Eigen::VectorXd activeSetStep(const World& world, const std::vector<ContactRow>& rows, const Eigen::VectorXd& b,
                              const std::vector<RowLimit>& limits, const Eigen::VectorXd& f) {
  const int n = static_cast<int>(rows.size());
  // What Gauss-Seidel drives each row's w to: 0, or a sliding row's target (row_gauss_seidel.h).
  // Its updates lower 1/2 f^T A f + (b - target)^T f, so that is the merit, with the target in.
  Eigen::VectorXd aim = b;
  for (int i = 0; i < n; ++i)
    if (limits[i].kind == RowLimit::Sliding) aim[i] -= limits[i].target;
  // The split: a pushing normal row and a friction row strictly inside its bounds hold w = aim.
  std::vector<int> index(n, -1);
  int free = 0;
  for (int i = 0; i < n; ++i)
    if (limits[i].kind == RowLimit::Normal && f[i] > 0) index[i] = free++;
  for (int i = 0; i < n; ++i) {
    const RowLimit& lim = limits[i];
    if (lim.kind == RowLimit::Normal || index[lim.normal] < 0) continue;
    const double bound = lim.mu * f[lim.normal];
    const bool inside = lim.kind == RowLimit::Static ? std::abs(f[i]) < bound : f[i] > 0 && f[i] < bound;
    if (inside) index[i] = free++;
  }
  if (free == 0) return f;

  // Each moving body's rows, with J's parts on it.
  std::vector<std::vector<Side>> on_body(world.bodies.size());
  for (int i = 0; i < n; ++i) {
    const ContactRow& r = rows[i];
    if (!world.bodies[r.a].is_static) on_body[r.a].push_back({i, -r.dir, -r.ra.cross(r.dir)});
    if (!world.bodies[r.b].is_static) on_body[r.b].push_back({i, r.dir, r.rb.cross(r.dir)});
  }
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) rhs[index[i]] = -aim[i];
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(free);
  for (std::size_t k = 0; k < on_body.size(); ++k) {
    const std::vector<Side>& sides = on_body[k];
    if (sides.empty()) continue;
    const RigidBody& body = world.bodies[k];
    const Eigen::Matrix3d inv_inertia = inverseInertiaWorld(body);
    // The velocity change the rows held at their bounds give this body, seen by the free rows.
    Eigen::Vector3d dv = Eigen::Vector3d::Zero(), dw = Eigen::Vector3d::Zero();
    for (const Side& s : sides)
      if (index[s.row] < 0 && f[s.row] != 0) dv += body.inv_mass * f[s.row] * s.lin, dw += f[s.row] * s.ang;
    dw = inv_inertia * dw;
    for (const Side& si : sides) {
      const int i = index[si.row];
      if (i < 0) continue;
      rhs[i] -= si.lin.dot(dv) + si.ang.dot(dw);
      const Eigen::Vector3d ang_i = inv_inertia * si.ang;
      for (const Side& sj : sides) {
        const int j = index[sj.row];
        if (j < 0) continue;
        const double a = body.inv_mass * si.lin.dot(sj.lin) + sj.ang.dot(ang_i);
        entries.emplace_back(i, j, a);
        if (i == j) diag[i] += a;
      }
    }
  }
  Eigen::SparseMatrix<double> a(free, free);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setMaxIterations(tuning::kActiveSetIterations);
  cg.setTolerance(1e-10);
  cg.compute(a);
  Eigen::VectorXd guess(free);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) guess[index[i]] = f[i];
  const Eigen::VectorXd solved = cg.solveWithGuess(rhs, guess);
  if (!solved.allFinite()) return f;

  // Back onto the bounds (normal rows first: friction bounds follow them), along the way from f to
  // the solution as far as the merit still falls.
  Eigen::VectorXd target = f;
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) target[i] = solved[index[i]];
  auto project = [&](const Eigen::VectorXd& g) {
    Eigen::VectorXd out = g;
    for (int i = 0; i < n; ++i)
      if (limits[i].kind == RowLimit::Normal) out[i] = std::max(0.0, g[i]);
    for (int i = 0; i < n; ++i) {
      const RowLimit& lim = limits[i];
      if (lim.kind == RowLimit::Normal) continue;
      const double bound = lim.mu * out[lim.normal];
      out[i] = std::clamp(g[i], lim.kind == RowLimit::Static ? -bound : 0.0, bound);
    }
    return out;
  };
  // The merit, which Gauss-Seidel lowers at every row it visits.
  auto merit = [&](const Eigen::VectorXd& g) {
    std::vector<Eigen::Vector3d> dv(world.bodies.size(), Eigen::Vector3d::Zero()), dl(world.bodies.size(), Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < on_body.size(); ++k)
      for (const Side& s : on_body[k]) dv[k] += g[s.row] * s.lin, dl[k] += g[s.row] * s.ang;
    double e = aim.dot(g);
    for (std::size_t k = 0; k < on_body.size(); ++k)
      if (!on_body[k].empty())
        e += 0.5 * (world.bodies[k].inv_mass * dv[k].squaredNorm() + dl[k].dot(inverseInertiaWorld(world.bodies[k]) * dl[k]));
    return e;
  };
  const double start = merit(f);
  for (double step = 1; step > 1e-3; step *= 0.25) {
    Eigen::VectorXd g = project(f + step * (target - f));
    if (merit(g) < start) return g;
  }
  return f;
}

}  // namespace tumble
