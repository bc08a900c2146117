#include "dynamics/row_gauss_seidel.h"

#include <algorithm>
#include <cmath>

namespace tumble {
namespace {

// A row as the sweep needs it. Static bodies keep their index: their inverse mass and inertia are
// zero, so the updates leave their (zero) velocity change untouched and no branch is needed.
struct Row {
  int a = 0, b = 0;
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();
  Eigen::Vector3d arm_a = Eigen::Vector3d::Zero(), arm_b = Eigen::Vector3d::Zero();   // J's angular parts
  Eigen::Vector3d ang_a = Eigen::Vector3d::Zero(), ang_b = Eigen::Vector3d::Zero();   // I^-1 arm per side
  double inv_mass_a = 0, inv_mass_b = 0;
  double inv_diag = 0;
};

}  // namespace

RowGaussSeidelResult solveRowsGaussSeidel(const World& world, const std::vector<ContactRow>& rows,
                                          const Eigen::VectorXd& b, const std::vector<RowLimit>& limits,
                                          const RowGaussSeidelSettings& settings,
                                          const Eigen::VectorXd& start) {
  RowGaussSeidelResult out;
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  // A first guess of zero pushes nothing: the same accelerations as no first guess.
  out.f = start.size() == n ? start : Eigen::VectorXd::Zero(n);
  static_cast<RowGaussSeidelSweeps&>(out) = sweepRowsGaussSeidel(world, rows, b, limits, settings, out.f);
  return out;
}

RowGaussSeidelSweeps sweepRowsGaussSeidel(const World& world, const std::vector<ContactRow>& rows,
                                          Eigen::Ref<const Eigen::VectorXd> b, const std::vector<RowLimit>& limits,
                                          const RowGaussSeidelSettings& settings, Eigen::Ref<Eigen::VectorXd> f) {
  const int n = static_cast<int>(rows.size());
  RowGaussSeidelSweeps out;
  if (n == 0) {
    out.converged = true;
    return out;
  }
  // Buffers kept between calls: a pile's rows take over 128 kB, which glibc would map and unmap
  // on every call (a page fault per page: a third of the time-stepping model's step, measured).
  // Indexed by body, but only the island's own bodies are written and read: the time-stepping
  // model solves a pile's islands one by one, and clearing arrays the size of the world for each
  // (a pile of 1000 boxes has a hundred islands a step) cost more than many of the solves.
  thread_local std::vector<Eigen::Matrix3d> inv_inertia;
  thread_local std::vector<char> used;   // all zero between calls
  thread_local std::vector<int> island_bodies;
  thread_local std::vector<Row> data_buffer;
  thread_local std::vector<Eigen::Vector3d> lin_buffer, ang_buffer;
  const std::size_t bodies = world.bodies.size();
  inv_inertia.resize(bodies);
  used.resize(bodies, 0);
  lin_buffer.resize(bodies);
  ang_buffer.resize(bodies);
  // Grown, never shrunk: a step solves a pile's big island and its small ones in turn, and a
  // resize back up to the big one's rows constructed every row again (1.7 MB of zeros a step, a
  // sixth of the sweeps' time in the 1000-box pile).
  if (data_buffer.size() < static_cast<std::size_t>(n)) data_buffer.resize(n);
  // Plain pointers for the sweeps: through the thread-local vectors the compiler reloaded each
  // one's address from thread storage on every row.
  Eigen::Vector3d* const lin = lin_buffer.data();
  Eigen::Vector3d* const ang = ang_buffer.data();
  Row* const data = data_buffer.data();
  island_bodies.clear();
  for (const ContactRow& r : rows)
    for (int k : {r.a, r.b})
      if (!used[k]) used[k] = 1, island_bodies.push_back(k);
  for (int k : island_bodies) {
    inv_inertia[k] = inverseInertiaWorld(world.bodies[k]);
    used[k] = 0;
    // Acceleration of each body from the forces so far: linear and angular parts.
    lin[k].setZero();
    ang[k].setZero();
  }

  for (int i = 0; i < n; ++i) {
    const ContactRow& r = rows[i];
    Row& d = data[i];
    d.a = r.a;
    d.b = r.b;
    d.dir = r.dir;
    d.arm_a = -r.ra.cross(r.dir);
    d.arm_b = r.rb.cross(r.dir);
    d.ang_a = inv_inertia[r.a] * d.arm_a;
    d.ang_b = inv_inertia[r.b] * d.arm_b;
    d.inv_mass_a = world.bodies[r.a].inv_mass;
    d.inv_mass_b = world.bodies[r.b].inv_mass;
    double diag = d.inv_mass_a + d.inv_mass_b + d.arm_a.dot(d.ang_a) + d.arm_b.dot(d.ang_b);
    d.inv_diag = diag > 0 ? 1 / diag : 0;   // a row between two static bodies takes no force
  }
  auto push = [lin, ang](const Row& d, double df) {
    lin[d.a] -= (df * d.inv_mass_a) * d.dir;
    lin[d.b] += (df * d.inv_mass_b) * d.dir;
    ang[d.a] += df * d.ang_a;
    ang[d.b] += df * d.ang_b;
  };
  for (int i = 0; i < n; ++i) push(data[i], f[i]);
  double* const f_of = f.data();
  const double* const b_of = b.data();
  const RowLimit* const limit_of = limits.data();
  const double stop = settings.tolerance * (b.lpNorm<Eigen::Infinity>() + 1e-300);
  // Rows come in runs on one pair of bodies (a contact's normal and friction rows, a manifold's
  // points): within a run, each row reads what the row before it wrote. The run's two bodies are
  // kept in locals, read once and written once, instead of through memory at every row (the same
  // arithmetic in the same order; 8 % of the sweeps' time in the 1000-box pile).
  thread_local std::vector<int> run_end_buffer;
  if (run_end_buffer.size() < static_cast<std::size_t>(n)) run_end_buffer.resize(n);
  int* const run_end = run_end_buffer.data();
  for (int i = n - 1; i >= 0; --i)
    run_end[i] = i + 1 < n && data[i + 1].a == data[i].a && data[i + 1].b == data[i].b ? run_end[i + 1] : i + 1;
  for (out.sweeps = 1; out.sweeps <= settings.max_sweeps; ++out.sweeps) {
    double largest_change = 0;
    for (int i = 0; i < n;) {
      const int end = run_end[i], ia = data[i].a, ib = data[i].b;
      Eigen::Vector3d lin_a = lin[ia], lin_b = lin[ib], ang_a = ang[ia], ang_b = ang[ib];
      for (; i < end; ++i) {
        const Row& d = data[i];
        const RowLimit& lim = limit_of[i];
        // A friction row with no force whose contact pushes with none (a speculative contact not
        // closing) is bounded to zero: whatever w is, it stays zero. Its w is not worth computing.
        if (lim.kind != RowLimit::Normal && f_of[i] == 0 && f_of[lim.normal] == 0) continue;
        double w = b_of[i] + d.dir.dot(lin_b - lin_a) + d.arm_a.dot(ang_a) + d.arm_b.dot(ang_b);
        double f = f_of[i], next = f;
        switch (lim.kind) {
          case RowLimit::Normal: next = std::max(0.0, f - w * d.inv_diag); break;
          case RowLimit::Static: {
            double bound = lim.mu * f_of[lim.normal];
            next = std::clamp(f - w * d.inv_diag, -bound, bound);
            break;
          }
          case RowLimit::Sliding:
            next = std::clamp(f + (lim.target - w) * d.inv_diag, 0.0, lim.mu * f_of[lim.normal]);
            break;
        }
        double df = next - f;
        if (df == 0) continue;
        f_of[i] = next;
        lin_a -= (df * d.inv_mass_a) * d.dir;
        lin_b += (df * d.inv_mass_b) * d.dir;
        ang_a += df * d.ang_a;
        ang_b += df * d.ang_b;
        if (d.inv_diag > 0) largest_change = std::max(largest_change, std::abs(df) / d.inv_diag);
      }
      lin[ia] = lin_a;
      lin[ib] = lin_b;
      ang[ia] = ang_a;
      ang[ib] = ang_b;
    }
    out.last_change = largest_change;
    if (!(largest_change > stop)) {
      out.converged = std::isfinite(largest_change);
      break;
    }
  }
  out.sweeps = std::min(out.sweeps, settings.max_sweeps);
  return out;
}

}  // namespace tumble
