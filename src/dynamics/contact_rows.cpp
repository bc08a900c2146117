#include "dynamics/contact_rows.h"

#include <algorithm>
#include <limits>

#include "dynamics/lcp/dantzig_solver.h"

namespace tumble {

void ContactRows::addContact(const World& world, const Contact& c, bool friction) {
  normal_row.push_back(static_cast<int>(rows.size()));
  rows.push_back(rowAlong(world, c, c.normal));
  if (!friction || c.friction <= 0) return;
  Eigen::Vector3d t1, t2;
  tangentsOf(c.normal, t1, t2);
  for (const Eigen::Vector3d& t : {t1, t2}) rows.push_back(rowAlong(world, c, t));
}

void ContactRows::addSlidingContact(const World& world, const Contact& c, const Eigen::Vector3d& against) {
  normal_row.push_back(static_cast<int>(rows.size()));
  rows.push_back(rowAlong(world, c, c.normal));
  rows.push_back(slideRow(world, c, against));
}

ContactRow slideRow(const World& world, const Contact& c, const Eigen::Vector3d& against) {
  return rowAlong(world, c, against);
}

std::pair<int, int> ContactRows::rowsOf(std::size_t k) const {
  const int end = k + 1 < normal_row.size() ? normal_row[k + 1] : size();
  return {normal_row[k], end};
}

ContactRows buildContactRows(const World& world, const std::vector<const Contact*>& set) {
  ContactRows out;
  for (const Contact* c : set) out.addContact(world, *c, true);
  return out;
}

std::vector<RowLimit> pyramidLimits(const ContactRows& rows, const std::vector<const Contact*>& set) {
  std::vector<RowLimit> limits(rows.rows.size());
  for (std::size_t k = 0; k < set.size(); ++k) {
    auto [r0, r_end] = rows.rowsOf(k);
    for (int r = r0 + 1; r < r_end; ++r) limits[r] = {RowLimit::Static, r0, set[k]->friction, 0};
  }
  return limits;
}

Eigen::VectorXd warmStart(const ContactRows& rows, const std::vector<const ImpulseRecord*>& last) {
  Eigen::VectorXd start = Eigen::VectorXd::Zero(rows.size());
  for (std::size_t k = 0; k < last.size(); ++k) {
    if (!last[k]) continue;
    auto [r0, r_end] = rows.rowsOf(k);
    for (int r = r0; r < r_end; ++r) start[r] = last[k]->impulse.dot(rows.rows[r].dir);
    start[r0] = std::max(0.0, start[r0]);
  }
  return start;
}

std::vector<Eigen::Vector3d> impulsePerContact(const ContactRows& rows, const Eigen::VectorXd& f, double scale) {
  std::vector<Eigen::Vector3d> impulse(rows.normal_row.size(), Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < impulse.size(); ++k) {
    auto [r0, r_end] = rows.rowsOf(k);
    for (int r = r0; r < r_end; ++r) impulse[k] += f[r] * scale * rows.rows[r].dir;
  }
  return impulse;
}

ImpulseRecord impulseRecord(const World& world, const Contact& c, const Eigen::Vector3d& impulse) {
  ImpulseRecord rec;
  rec.a = c.a;
  rec.b = c.b;
  rec.local = ImpulseMemory::localPoint(world, c);
  rec.impulse = impulse;
  return rec;
}

ContactLcp buildContactLcp(const World& world, const std::vector<const Contact*>& set,
                           const std::vector<char>& friction) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ContactLcp out;
  for (std::size_t i = 0; i < set.size(); ++i) out.addContact(world, *set[i], friction[i]);
  const int n = out.size();
  std::vector<int> friction_of(n, -1);
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < set.size(); ++k) {
    auto [r0, r_end] = out.rowsOf(k);
    for (int r = r0 + 1; r < r_end; ++r) {
      friction_of[r] = r0;
      mu[r] = set[k]->friction;
    }
  }
  out.problem.A = delassus(world, out.rows);
  out.problem.b = Eigen::VectorXd::Zero(n);
  out.problem.lo = Eigen::VectorXd::Zero(n);
  out.problem.hi = Eigen::VectorXd::Constant(n, kInf);
  out.problem.friction_of = std::move(friction_of);
  out.problem.mu = std::move(mu);
  return out;
}

lcp::LcpResult solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats) {
  // Redundant contacts (four corners of a face) leave the split of the normal force between them
  // free, so the friction bounds +-mu f_n need not settle to the last bit between passes: settle to
  // 1e-9 of the largest bound (far below any force that moves a body measurably).
  lcp::DantzigSettings settings;
  settings.friction_tolerance = tuning::kFrictionTolerance;
  settings.max_friction_passes = tuning::kMaxFrictionPasses;
  lcp::LcpResult r = lcp::solveDantzig(p, settings);
  stats.pivots += r.iterations;
  if (r.status != lcp::LcpStatus::Solved) ++stats.failures;
  return r;
}

bool usableLcpAnswer(const lcp::LcpResult& r, const lcp::LcpProblem& p) {
  if (r.status == lcp::LcpStatus::Solved) return true;
  if (!r.f.allFinite()) return false;
  return r.residual.complementarity <= tuning::kUsableComplementarity * (p.b.lpNorm<Eigen::Infinity>() + 1);
}

double normalVelocity(const World& world, const Contact& c) {
  return rowVelocity(world, rowAlong(world, c, c.normal));
}

}  // namespace tumble
