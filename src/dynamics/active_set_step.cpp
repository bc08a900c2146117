#include "dynamics/active_set_step.h"

#include <algorithm>
#include <cmath>

#include "dynamics/scratch_vector.h"
#include "dynamics/settings.h"

namespace tumble {
namespace {

// A row's part of J on one body: the sign of the side, and its linear and angular parts.
struct Side {
  int row = 0;
  Eigen::Vector3d lin, ang;   // J's parts (dir, r x dir), signed
};

// Buffers kept between calls on each thread (a step solves its islands on several): sized by the
// largest island seen, so a warm step allocates nothing here.
struct Scratch {
  ScratchVector aim, rhs, diag, x, r, z, dir, a_dir, inv_diag, target, trial;
  std::vector<int> index;
  std::vector<int> local_of;          // per world body: its place in `bodies`, -1 between calls
  std::vector<int> bodies;            // the island's moving bodies, in index order
  std::vector<int> first, cursor;     // body j's sides are sides[first[j], first[j + 1])
  std::vector<Side> sides;
  std::vector<Eigen::Matrix3d> inv_inertia;
  std::vector<Eigen::Vector3d> dv, dl;
};

}  // namespace

void activeSetStep(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                   const std::vector<RowLimit>& limits, Eigen::Ref<const Eigen::VectorXd> f,
                   Eigen::Ref<Eigen::VectorXd> out) {
  thread_local Scratch s;
  const int n = static_cast<int>(rows.size());
  // What Gauss-Seidel drives each row's w to: 0, or a sliding row's target (row_gauss_seidel.h).
  // Its updates lower 1/2 f^T A f + (b - target)^T f, so that is the merit, with the target in.
  auto aim = s.aim.view(n);
  aim = b;
  for (int i = 0; i < n; ++i)
    if (limits[i].kind == RowLimit::Sliding) aim[i] -= limits[i].target;
  // The split: a pushing normal row and a friction row strictly inside its bounds hold w = aim.
  std::vector<int>& index = s.index;
  index.assign(n, -1);
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
  if (free == 0) {
    out = f;
    return;
  }

  // The island's moving bodies, in index order, and each one's rows with J's parts on it, in row
  // order: the loops below visit only these, not the whole world.
  s.local_of.resize(world.bodies.size(), -1);
  s.bodies.clear();
  for (const ContactRow& r : rows)
    for (int k : {r.a, r.b})
      if (!world.bodies[k].is_static && s.local_of[k] < 0) s.local_of[k] = 0, s.bodies.push_back(k);
  std::sort(s.bodies.begin(), s.bodies.end());
  const int nb = static_cast<int>(s.bodies.size());
  for (int j = 0; j < nb; ++j) s.local_of[s.bodies[j]] = j;
  s.first.assign(nb + 1, 0);
  for (const ContactRow& r : rows)
    for (int k : {r.a, r.b})
      if (!world.bodies[k].is_static) ++s.first[s.local_of[k] + 1];
  for (int j = 0; j < nb; ++j) s.first[j + 1] += s.first[j];
  s.cursor.assign(s.first.begin(), s.first.end() - 1);
  s.sides.resize(s.first[nb]);
  for (int i = 0; i < n; ++i) {
    const ContactRow& r = rows[i];
    if (!world.bodies[r.a].is_static) s.sides[s.cursor[s.local_of[r.a]]++] = {i, -r.dir, -r.ra.cross(r.dir)};
    if (!world.bodies[r.b].is_static) s.sides[s.cursor[s.local_of[r.b]]++] = {i, r.dir, r.rb.cross(r.dir)};
  }
  for (int k : s.bodies) s.local_of[k] = -1;
  const Side* const sides = s.sides.data();
  const int* const first = s.first.data();
  // The free rows' right-hand side: -aim, less what the rows held at their bounds already do.
  s.inv_inertia.resize(nb);
  auto rhs = s.rhs.view(free), diag = s.diag.view(free);
  rhs.setZero();
  diag.setZero();
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) rhs[index[i]] = -aim[i];
  for (int j = 0; j < nb; ++j) {
    const RigidBody& body = world.bodies[s.bodies[j]];
    const Eigen::Matrix3d& inv_inertia = s.inv_inertia[j] = inverseInertiaWorld(body);
    Eigen::Vector3d dv = Eigen::Vector3d::Zero(), dw = Eigen::Vector3d::Zero();
    for (int q = first[j]; q < first[j + 1]; ++q) {
      const Side& side = sides[q];
      if (index[side.row] < 0 && f[side.row] != 0) dv += body.inv_mass * f[side.row] * side.lin, dw += f[side.row] * side.ang;
    }
    dw = inv_inertia * dw;
    for (int q = first[j]; q < first[j + 1]; ++q) {
      const Side& si = sides[q];
      const int i = index[si.row];
      if (i < 0) continue;
      rhs[i] -= si.lin.dot(dv) + si.ang.dot(dw);
      diag[i] += body.inv_mass * si.lin.squaredNorm() + si.ang.dot(inv_inertia * si.ang);
    }
  }
  // y = A_ff x without forming A_ff: each body sums the impulses of its free rows, and each row
  // reads the velocity change they give (a row between two static bodies has diag 0 and no part).
  // A body carrying n rows costs O(n) here where an assembled A_ff had n^2 entries on it: a crib
  // plank under twelve crossings of four points has 144 rows, 20 000 entries.
  auto apply = [&](const auto& x, auto& y) {
    y.setZero();
    for (int j = 0; j < nb; ++j) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero(), l = Eigen::Vector3d::Zero();
      for (int q = first[j]; q < first[j + 1]; ++q) {
        const Side& side = sides[q];
        if (index[side.row] >= 0) p += x[index[side.row]] * side.lin, l += x[index[side.row]] * side.ang;
      }
      const Eigen::Vector3d dv = world.bodies[s.bodies[j]].inv_mass * p, dw = s.inv_inertia[j] * l;
      for (int q = first[j]; q < first[j + 1]; ++q) {
        const Side& side = sides[q];
        if (index[side.row] >= 0) y[index[side.row]] += side.lin.dot(dv) + side.ang.dot(dw);
      }
    }
  };
  // Conjugate gradients preconditioned by the diagonal, from the current answer, until the
  // residual is 1e-10 of the right-hand side or the iterations run out.
  auto x = s.x.view(free), r = s.r.view(free), z = s.z.view(free), dir = s.dir.view(free),
       a_dir = s.a_dir.view(free), inv_diag = s.inv_diag.view(free);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) x[index[i]] = f[i];
  inv_diag = diag.unaryExpr([](double d) { return d > 0 ? 1 / d : 0.0; });
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
  const auto& solved = x;
  if (!solved.allFinite()) {
    out = f;
    return;
  }

  // Back onto the bounds (normal rows first: friction bounds follow them), along the way from f to
  // the solution as far as the merit still falls.
  auto target = s.target.view(n);
  target = f;
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) target[i] = solved[index[i]];
  // g onto the bounds, in place (a friction row reads its normal row's projected value).
  auto project = [&](auto& g) {
    for (int i = 0; i < n; ++i)
      if (limits[i].kind == RowLimit::Normal) g[i] = std::max(0.0, g[i]);
    for (int i = 0; i < n; ++i) {
      const RowLimit& lim = limits[i];
      if (lim.kind == RowLimit::Normal) continue;
      const double bound = lim.mu * g[lim.normal];
      g[i] = std::clamp(g[i], lim.kind == RowLimit::Static ? -bound : 0.0, bound);
    }
  };
  // The merit, which Gauss-Seidel lowers at every row it visits.
  s.dv.resize(nb);
  s.dl.resize(nb);
  auto merit = [&](const auto& g) {
    for (int j = 0; j < nb; ++j) {
      Eigen::Vector3d& dv = s.dv[j] = Eigen::Vector3d::Zero();
      Eigen::Vector3d& dl = s.dl[j] = Eigen::Vector3d::Zero();
      for (int q = first[j]; q < first[j + 1]; ++q) dv += g[sides[q].row] * sides[q].lin, dl += g[sides[q].row] * sides[q].ang;
    }
    double e = aim.dot(g);
    for (int j = 0; j < nb; ++j)
      e += 0.5 * (world.bodies[s.bodies[j]].inv_mass * s.dv[j].squaredNorm() + s.dl[j].dot(s.inv_inertia[j] * s.dl[j]));
    return e;
  };
  const double start = merit(f);
  auto trial = s.trial.view(n);
  for (double step = 1; step > 1e-3; step *= 0.25) {
    trial = f + step * (target - f);
    project(trial);
    if (merit(trial) < start) {
      out = trial;
      return;
    }
  }
  out = f;
}

}  // namespace tumble
