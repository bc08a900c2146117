#include "dynamics/row_gauss_seidel.h"

#include <algorithm>
#include <cmath>

namespace tumble {
namespace {

// What a unit force along a row does to one of its bodies (zero for a static body).
struct Side {
  int body = -1;
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();    // M^-1 J^T: velocity change per unit force
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();       // J: signed direction and arm
  Eigen::Vector3d arm = Eigen::Vector3d::Zero();
};

Side sideOf(const World& world, const std::vector<Eigen::Matrix3d>& inv_inertia, int index,
            const Eigen::Vector3d& r, const Eigen::Vector3d& dir, double sign) {
  Side s;
  const RigidBody& body = world.bodies[index];
  if (body.is_static) return s;
  s.body = index;
  s.dir = sign * dir;
  s.arm = sign * r.cross(dir);
  s.linear = s.dir * body.inv_mass;
  s.angular = inv_inertia[index] * s.arm;
  return s;
}

}  // namespace

RowGaussSeidelResult solveRowsGaussSeidel(const World& world, const std::vector<ContactRow>& rows,
                                          const Eigen::VectorXd& b, const std::vector<RowLimit>& limits,
                                          const RowGaussSeidelSettings& settings) {
  const int n = static_cast<int>(rows.size());
  RowGaussSeidelResult out;
  out.f = Eigen::VectorXd::Zero(n);
  if (n == 0) {
    out.converged = true;
    return out;
  }
  std::vector<Eigen::Matrix3d> inv_inertia(world.bodies.size(), Eigen::Matrix3d::Zero());
  std::vector<char> used(world.bodies.size(), 0);
  for (const ContactRow& r : rows) used[r.a] = used[r.b] = 1;
  for (std::size_t k = 0; k < world.bodies.size(); ++k)
    if (used[k]) inv_inertia[k] = inverseInertiaWorld(world.bodies[k]);

  std::vector<Side> sa(n), sb(n);
  Eigen::VectorXd inv_diag(n);
  for (int i = 0; i < n; ++i) {
    sa[i] = sideOf(world, inv_inertia, rows[i].a, rows[i].ra, rows[i].dir, -1);
    sb[i] = sideOf(world, inv_inertia, rows[i].b, rows[i].rb, rows[i].dir, +1);
    double d = sa[i].dir.dot(sa[i].linear) + sa[i].arm.dot(sa[i].angular) + sb[i].dir.dot(sb[i].linear) +
               sb[i].arm.dot(sb[i].angular);
    inv_diag[i] = d > 0 ? 1 / d : 0;   // a row between two static bodies takes no force
  }
  // Acceleration of each body from the forces so far: linear and angular parts.
  std::vector<Eigen::Vector3d> lin(world.bodies.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> ang(world.bodies.size(), Eigen::Vector3d::Zero());
  auto rowAccel = [&](int i) {
    double w = b[i];
    for (const Side* s : {&sa[i], &sb[i]})
      if (s->body >= 0) w += s->dir.dot(lin[s->body]) + s->arm.dot(ang[s->body]);
    return w;
  };
  const double stop = settings.tolerance * (b.lpNorm<Eigen::Infinity>() + 1e-300);
  for (out.sweeps = 1; out.sweeps <= settings.max_sweeps; ++out.sweeps) {
    double largest_change = 0;
    for (int i = 0; i < n; ++i) {
      const RowLimit& lim = limits[i];
      double w = rowAccel(i), f = out.f[i], next = f;
      switch (lim.kind) {
        case RowLimit::Normal: next = std::max(0.0, f - w * inv_diag[i]); break;
        case RowLimit::Static: {
          double bound = lim.mu * out.f[lim.normal];
          next = std::clamp(f - w * inv_diag[i], -bound, bound);
          break;
        }
        case RowLimit::Sliding:
          next = std::clamp(f + (lim.target - w) * inv_diag[i], 0.0, lim.mu * out.f[lim.normal]);
          break;
      }
      double df = next - f;
      if (df == 0) continue;
      out.f[i] = next;
      for (const Side* s : {&sa[i], &sb[i]})
        if (s->body >= 0) {
          lin[s->body] += df * s->linear;
          ang[s->body] += df * s->angular;
        }
      if (inv_diag[i] > 0) largest_change = std::max(largest_change, std::abs(df) / inv_diag[i]);
    }
    if (!(largest_change > stop)) {
      out.converged = std::isfinite(largest_change);
      break;
    }
  }
  out.sweeps = std::min(out.sweeps, settings.max_sweeps);
  return out;
}

}  // namespace tumble
