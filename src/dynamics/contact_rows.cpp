#include "dynamics/contact_rows.h"

#include <algorithm>
#include <limits>

#include "dynamics/lcp/dantzig_solver.h"
#include "dynamics/lcp/lemke_friction.h"

namespace tumble {
namespace {

// The problem of rows already built for `set`: A, zero b, bounds and friction indices; its
// vectors reuse their storage.
void fillContactLcp(const World& world, std::span<const Contact* const> set, ContactLcp& out) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int n = out.size();
  lcp::LcpProblem& p = out.problem;
  p.friction_of.assign(n, -1);
  p.mu.setZero(n);
  for (std::size_t k = 0; k < set.size(); ++k) {
    auto [r0, r_end] = out.rowsOf(k);
    for (int r = r0 + 1; r < r_end; ++r) {
      p.friction_of[r] = r0;
      p.mu[r] = set[k]->friction;
    }
  }
  delassus(world, out.rows, p.A);
  p.b.setZero(n);
  p.lo.setZero(n);
  p.hi.setConstant(n, kInf);
}

}  // namespace

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

ContactRows buildContactRows(const World& world, std::span<const Contact* const> set) {
  ContactRows out;
  buildContactRows(world, set, out);
  return out;
}

void buildContactRows(const World& world, std::span<const Contact* const> set, ContactRows& out) {
  out.rows.clear();
  out.normal_row.clear();
  for (const Contact* c : set) out.addContact(world, *c, true);
}

std::vector<RowLimit> pyramidLimits(const ContactRows& rows, std::span<const Contact* const> set) {
  std::vector<RowLimit> limits;
  pyramidLimits(rows, set, limits);
  return limits;
}

void pyramidLimits(const ContactRows& rows, std::span<const Contact* const> set, std::vector<RowLimit>& out) {
  out.assign(rows.rows.size(), RowLimit{});
  for (std::size_t k = 0; k < set.size(); ++k) {
    auto [r0, r_end] = rows.rowsOf(k);
    for (int r = r0 + 1; r < r_end; ++r) out[r] = {RowLimit::Static, r0, set[k]->friction, 0};
  }
}

Eigen::VectorXd warmStart(const ContactRows& rows, std::span<const ImpulseRecord* const> last) {
  Eigen::VectorXd start(rows.size());
  warmStart(rows, last, start);
  return start;
}

void warmStart(const ContactRows& rows, std::span<const ImpulseRecord* const> last, Eigen::Ref<Eigen::VectorXd> out) {
  out.setZero();
  for (std::size_t k = 0; k < last.size(); ++k) {
    if (!last[k]) continue;
    auto [r0, r_end] = rows.rowsOf(k);
    for (int r = r0; r < r_end; ++r) out[r] = last[k]->impulse.dot(rows.rows[r].dir);
    out[r0] = std::max(0.0, out[r0]);
  }
}

std::vector<Eigen::Vector3d> impulsePerContact(const ContactRows& rows, const Eigen::VectorXd& f, double scale) {
  std::vector<Eigen::Vector3d> impulse(rows.normal_row.size());
  for (std::size_t k = 0; k < impulse.size(); ++k) impulse[k] = impulseOfContact(rows, f, k, scale);
  return impulse;
}

Eigen::Vector3d impulseOfContact(const ContactRows& rows, Eigen::Ref<const Eigen::VectorXd> f, std::size_t k,
                                 double scale) {
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  auto [r0, r_end] = rows.rowsOf(k);
  for (int r = r0; r < r_end; ++r) impulse += f[r] * scale * rows.rows[r].dir;
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

ContactLcp buildContactLcp(const World& world, std::span<const Contact* const> set,
                           const std::vector<char>& friction) {
  ContactLcp out;
  for (std::size_t i = 0; i < set.size(); ++i) out.addContact(world, *set[i], friction[i]);
  fillContactLcp(world, set, out);
  return out;
}

void buildContactLcp(const World& world, std::span<const Contact* const> set, ContactLcp& out) {
  out.rows.clear();
  out.normal_row.clear();
  for (const Contact* c : set) out.addContact(world, *c, true);
  fillContactLcp(world, set, out);
}

lcp::LcpResult solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats) {
  lcp::LcpResult r;
  solveContactLcp(p, stats, r);
  return r;
}

void solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats, lcp::LcpResult& r) {
  // Redundant contacts (four corners of a face) leave the split of the normal force between them
  // free, so the friction bounds +-mu f_n need not settle to the last bit between passes: settle to
  // 1e-9 of the largest bound (far below any force that moves a body measurably).
  lcp::DantzigSettings settings;
  settings.friction_tolerance = tuning::kFrictionTolerance;
  settings.max_friction_passes = tuning::kMaxFrictionPasses;
  lcp::solveDantzig(p, settings, r);
  stats.pivots += r.iterations;
  // Friction passes that do not settle (their fixed point need not contract): the same problem by
  // complementary pivoting, which reaches an answer where one exists (lcp/lemke_friction.h), on
  // problems small enough for its dense O(n^3) factorisations. Its answer is taken where it is as
  // near exact as a usable pivoting answer must be.
  if (!usableLcpAnswer(r, p) && p.size() <= tuning::kLemkeMaxRows && lcp::lemkeCovers(p)) {
    thread_local lcp::LcpResult settled;
    lcp::solveLemkeFriction(p, lcp::LemkeSettings{}, settled);
    stats.pivots += settled.iterations;
    if (usableLcpAnswer(settled, p)) {
      std::swap(r, settled);
      ++stats.lemke_settled;
      return;
    }
  }
  if (r.status != lcp::LcpStatus::Solved) ++stats.failures;
}

bool usableLcpAnswer(const lcp::LcpResult& r, const lcp::LcpProblem& p) {
  if (r.status == lcp::LcpStatus::Solved) return true;
  if (!r.f.allFinite()) return false;
  return r.residual.complementarity <= tuning::kUsableComplementarity * (p.b.lpNorm<Eigen::Infinity>() + 1);
}

double normalVelocity(const World& world, const Contact& c) {
  return rowVelocity(world, rowAlong(world, c, c.normal));
}

double normalVelocity(const World& world, const Contact& c, const std::vector<Eigen::Vector3d>& spin) {
  const ContactRow row = rowAlong(world, c, c.normal);
  const RigidBody& A = world.bodies[row.a];
  const RigidBody& B = world.bodies[row.b];
  return row.dir.dot(pointVelocity(B, spin[row.b], B.x + row.rb) - pointVelocity(A, spin[row.a], A.x + row.ra));
}

}  // namespace tumble
