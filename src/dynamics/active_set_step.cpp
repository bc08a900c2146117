#include "dynamics/active_set_step.h"

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
  // The island's bodies, in index order: the loops below visit only these, not the whole world.
  std::vector<std::size_t> carrying;
  for (std::size_t k = 0; k < on_body.size(); ++k)
    if (!on_body[k].empty()) carrying.push_back(k);
  // The free rows' right-hand side: -aim, less what the rows held at their bounds already do.
  std::vector<Eigen::Matrix3d> inv_inertia(world.bodies.size(), Eigen::Matrix3d::Zero());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free), diag = Eigen::VectorXd::Zero(free);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) rhs[index[i]] = -aim[i];
  for (std::size_t k : carrying) {
    const std::vector<Side>& sides = on_body[k];
    const RigidBody& body = world.bodies[k];
    inv_inertia[k] = inverseInertiaWorld(body);
    Eigen::Vector3d dv = Eigen::Vector3d::Zero(), dw = Eigen::Vector3d::Zero();
    for (const Side& s : sides)
      if (index[s.row] < 0 && f[s.row] != 0) dv += body.inv_mass * f[s.row] * s.lin, dw += f[s.row] * s.ang;
    dw = inv_inertia[k] * dw;
    for (const Side& si : sides) {
      const int i = index[si.row];
      if (i < 0) continue;
      rhs[i] -= si.lin.dot(dv) + si.ang.dot(dw);
      diag[i] += body.inv_mass * si.lin.squaredNorm() + si.ang.dot(inv_inertia[k] * si.ang);
    }
  }
  // y = A_ff x without forming A_ff: each body sums the impulses of its free rows, and each row
  // reads the velocity change they give (a row between two static bodies has diag 0 and no part).
  // A body carrying n rows costs O(n) here where an assembled A_ff had n^2 entries on it: a crib
  // plank under twelve crossings of four points has 144 rows, 20 000 entries.
  auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y.setZero(free);
    for (std::size_t k : carrying) {
      const std::vector<Side>& sides = on_body[k];
      Eigen::Vector3d p = Eigen::Vector3d::Zero(), l = Eigen::Vector3d::Zero();
      for (const Side& s : sides)
        if (index[s.row] >= 0) p += x[index[s.row]] * s.lin, l += x[index[s.row]] * s.ang;
      const Eigen::Vector3d dv = world.bodies[k].inv_mass * p, dw = inv_inertia[k] * l;
      for (const Side& s : sides)
        if (index[s.row] >= 0) y[index[s.row]] += s.lin.dot(dv) + s.ang.dot(dw);
    }
  };
  // Conjugate gradients preconditioned by the diagonal, from the current answer, until the
  // residual is 1e-10 of the right-hand side or the iterations run out.
  Eigen::VectorXd x(free), r(free), z(free), dir(free), a_dir(free);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) x[index[i]] = f[i];
  const Eigen::VectorXd inv_diag = diag.unaryExpr([](double d) { return d > 0 ? 1 / d : 0.0; });
  apply(x, r);
  r = rhs - r;
  const double stop = 1e-10 * rhs.norm();
  z = r.cwiseProduct(inv_diag);
  dir = z;
  double rz = r.dot(z);
  for (int it = 0; it < tuning::kActiveSetIterations && r.norm() > stop; ++it) {
    apply(dir, a_dir);
    const double curvature = dir.dot(a_dir);
    if (!(curvature > 0)) break;   // a direction along A's null space (redundant rows): no further
    const double alpha = rz / curvature;
    x += alpha * dir;
    r -= alpha * a_dir;
    z = r.cwiseProduct(inv_diag);
    const double rz_next = r.dot(z);
    dir = z + (rz_next / rz) * dir;
    rz = rz_next;
  }
  const Eigen::VectorXd& solved = x;
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
    for (std::size_t k : carrying)
      for (const Side& s : on_body[k]) dv[k] += g[s.row] * s.lin, dl[k] += g[s.row] * s.ang;
    double e = aim.dot(g);
    for (std::size_t k : carrying)
      e += 0.5 * (world.bodies[k].inv_mass * dv[k].squaredNorm() + dl[k].dot(inv_inertia[k] * dl[k]));
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
