#include "dynamics/joints/generic_gauss_seidel.h"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_jacobian.h"

namespace tumble {

GenericSweeps solveGenericGaussSeidel(const World& world, const std::vector<JointRow>& rows, const lcp::LcpProblem& p,
                                      const Eigen::VectorXd& start, int max_sweeps, double tolerance,
                                      const std::vector<char>& one_sided) {
  const int n = static_cast<int>(rows.size());
  const std::size_t bodies = world.bodies.size();
  GenericSweeps out;
  out.f = start.size() == n ? start : Eigen::VectorXd::Zero(n);
  // M^-1 J^T per row and side, and 1 / A_ii; the world and static bodies take nothing.
  std::vector<Eigen::Matrix3d> inv_inertia(bodies, Eigen::Matrix3d::Zero());
  std::vector<double> inv_mass(bodies, 0);
  for (std::size_t k = 0; k < bodies; ++k)
    if (!world.bodies[k].is_static) {
      inv_inertia[k] = inverseInertiaWorld(world.bodies[k]);
      inv_mass[k] = world.bodies[k].inv_mass;
    }
  auto moves = [&](int body) { return body >= 0 && inv_mass[body] > 0; };
  std::vector<Eigen::Vector3d> la(n), aa(n), lb(n), ab(n);
  std::vector<double> inv_diag(n, 0);
  for (int i = 0; i < n; ++i) {
    const JointRow& r = rows[i];
    la[i] = aa[i] = lb[i] = ab[i] = Eigen::Vector3d::Zero();
    if (moves(r.a)) la[i] = inv_mass[r.a] * r.lin_a, aa[i] = inv_inertia[r.a] * r.ang_a;
    if (moves(r.b)) lb[i] = inv_mass[r.b] * r.lin_b, ab[i] = inv_inertia[r.b] * r.ang_b;
    const double diag = r.lin_a.dot(la[i]) + r.ang_a.dot(aa[i]) + r.lin_b.dot(lb[i]) + r.ang_b.dot(ab[i]);
    inv_diag[i] = diag > 0 ? 1 / diag : 0;
  }
  std::vector<Eigen::Vector3d> dv(bodies, Eigen::Vector3d::Zero()), dw(bodies, Eigen::Vector3d::Zero());
  auto push = [&](int i, double df) {
    const JointRow& r = rows[i];
    if (moves(r.a)) dv[r.a] += df * la[i], dw[r.a] += df * aa[i];
    if (moves(r.b)) dv[r.b] += df * lb[i], dw[r.b] += df * ab[i];
  };
  for (int i = 0; i < n; ++i)
    if (out.f[i] != 0) push(i, out.f[i]);
  double scale = 0;   // the largest finite |b|: a one-sided row's -inf asks for its bound, not a size
  for (int i = 0; i < n; ++i)
    if (std::isfinite(p.b[i])) scale = std::max(scale, std::abs(p.b[i]));
  const double stop = tolerance * (scale + 1e-300);
  for (out.sweeps = 1; out.sweeps <= max_sweeps; ++out.sweeps) {
    double largest = 0;
    for (int i = 0; i < n; ++i) {
      const JointRow& r = rows[i];
      double w = p.b[i];
      if (moves(r.a)) w += r.lin_a.dot(dv[r.a]) + r.ang_a.dot(dw[r.a]);
      if (moves(r.b)) w += r.lin_b.dot(dv[r.b]) + r.ang_b.dot(dw[r.b]);
      double lo = p.lo[i], hi = p.hi[i];
      if (p.isFriction(i)) {
        hi = p.mu[i] * std::max(0.0, out.f[p.friction_of[i]]);
        lo = !one_sided.empty() && one_sided[i] ? 0.0 : -hi;
      }
      // A row that moves nothing is only kept within its bounds (and an infinite w would give 0 x inf).
      const double next = std::clamp(out.f[i] - (inv_diag[i] > 0 ? w * inv_diag[i] : 0.0), lo, hi);
      const double df = next - out.f[i];
      if (df == 0) continue;
      out.f[i] = next;
      push(i, df);
      if (inv_diag[i] > 0) largest = std::max(largest, std::abs(df) / inv_diag[i]);
    }
    if (!(largest > stop)) {
      out.converged = std::isfinite(largest);
      break;
    }
  }
  out.sweeps = std::min(out.sweeps, max_sweeps);
  return out;
}

}  // namespace tumble
