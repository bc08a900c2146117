#include "dynamics/joints/contact_joint_lcp.h"

#include <limits>

#include "dynamics/island_impulses.h"
#include "dynamics/joints/generic_gauss_seidel.h"
#include "dynamics/settings.h"

namespace tumble {

JointRow asGenericRow(const ContactRow& row) {
  JointRow r;
  r.a = row.a;
  r.b = row.b;
  r.lin_a = -row.dir;
  r.ang_a = -row.ra.cross(row.dir);
  r.lin_b = row.dir;
  r.ang_b = row.rb.cross(row.dir);
  return r;
}

namespace {

// Contact rows first, so the friction rows' normal indices (findex) stay as they are.
std::vector<JointRow> allRows(const std::vector<ContactRow>& contact_rows, const std::vector<JointRow>& joints) {
  std::vector<JointRow> all;
  all.reserve(contact_rows.size() + joints.size());
  for (const ContactRow& row : contact_rows) all.push_back(asGenericRow(row));
  all.insert(all.end(), joints.begin(), joints.end());
  return all;
}

// The combined problem's b and bounds, without A.
lcp::LcpProblem boundsOf(const lcp::LcpProblem& contacts, const std::vector<JointRow>& joints, const Eigen::VectorXd& joint_b) {
  const int nc = contacts.size(), nj = static_cast<int>(joints.size()), n = nc + nj;
  lcp::LcpProblem p;
  p.b.resize(n);
  p.b << contacts.b, joint_b;
  p.lo.resize(n);
  p.hi.resize(n);
  p.lo << contacts.lo, Eigen::VectorXd::Zero(nj);
  p.hi << contacts.hi, Eigen::VectorXd::Zero(nj);
  p.friction_of = contacts.friction_of;
  p.friction_of.resize(n, -1);
  p.mu = Eigen::VectorXd::Zero(n);
  if (contacts.mu.size() == nc) p.mu.head(nc) = contacts.mu;
  for (int i = 0; i < nj; ++i) {
    p.lo[nc + i] = joints[i].lo;
    p.hi[nc + i] = joints[i].hi;
  }
  return p;
}

}  // namespace

lcp::LcpProblem withJointRows(const World& world, const lcp::LcpProblem& contacts,
                              const std::vector<ContactRow>& contact_rows, const std::vector<JointRow>& joints,
                              const Eigen::VectorXd& joint_b) {
  lcp::LcpProblem p = boundsOf(contacts, joints, joint_b);
  p.A = jointDelassus(world, allRows(contact_rows, joints));
  return p;
}

Eigen::VectorXd sweepContactsWithJoints(const World& world, const ContactRows& contacts,
                                        const std::vector<RowLimit>& limits, const Eigen::VectorXd& contact_b,
                                        const std::vector<JointRow>& joints, const Eigen::VectorXd& joint_b,
                                        const Eigen::VectorXd& contact_start, ContactSolveStats& stats,
                                        double tolerance) {
  // The pyramid limits as bounds: a normal row pushes, a friction row within mu of its normal's.
  const int nc = contacts.size(), nj = static_cast<int>(joints.size()), n = nc + nj;
  lcp::LcpProblem p;
  p.b.resize(n);
  p.b << contact_b, joint_b;
  p.lo = Eigen::VectorXd::Zero(n);
  p.hi = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  p.friction_of.assign(n, -1);
  p.mu = Eigen::VectorXd::Zero(n);
  std::vector<char> one_sided(n, 0);
  for (int i = 0; i < nc; ++i)
    if (limits[i].kind != RowLimit::Normal) {
      p.friction_of[i] = limits[i].normal;
      p.mu[i] = limits[i].mu;
    }
  // A slide's row: opposes the slide by at most mu f_n, asking for the slide's stop (its target)
  // at most, as row_gauss_seidel.h's Sliding rows do.
  for (int i = 0; i < nc; ++i)
    if (limits[i].kind == RowLimit::Sliding) {
      one_sided[i] = 1;
      p.b[i] -= limits[i].target;
    }
  for (int i = 0; i < nj; ++i) {
    p.lo[nc + i] = joints[i].lo;
    p.hi[nc + i] = joints[i].hi;
  }
  Eigen::VectorXd start = Eigen::VectorXd::Zero(n);
  if (contact_start.size() == nc) start.head(nc) = contact_start;
  GenericSweeps swept = solveGenericGaussSeidel(world, allRows(contacts.rows, joints), p, start,
                                                IslandImpulseSettings{}.max_sweeps, tolerance, one_sided);
  ++stats.iterative_islands;
  stats.sweeps += swept.sweeps;
  if (!swept.converged) ++stats.unconverged_sweeps;
  return swept.f;
}

Eigen::VectorXd solveContactsWithJoints(World& world, const ContactLcp& contacts, const std::vector<JointRow>& joints,
                                        const Eigen::VectorXd& joint_b, const ContactJointSettings& settings,
                                        ContactSolveStats& stats) {
  const int nc = contacts.size(), nj = static_cast<int>(joints.size()), n = nc + nj;
  Eigen::VectorXd f;
  bool solved = false;
  if (n <= settings.max_direct_rows) {
    const lcp::LcpProblem p = withJointRows(world, contacts.problem, contacts.rows, joints, joint_b);
    lcp::LcpResult r = solveContactLcp(p, stats);
    solved = usableLcpAnswer(r, p);
    if (solved) f = std::move(r.f);
    else ++stats.iterative_fallbacks;
  }
  if (!solved) {
    // Too large to pivot, or pivoting stopped short: the same rows by projected Gauss-Seidel, the
    // contacts warm-started from the last step's impulses, the joints from zero.
    Eigen::VectorXd start = Eigen::VectorXd::Zero(n);
    if (settings.contact_start.size() == nc) start.head(nc) = settings.contact_start;
    GenericSweeps swept = solveGenericGaussSeidel(world, allRows(contacts.rows, joints),
                                                  boundsOf(contacts.problem, joints, joint_b), start,
                                                  settings.max_sweeps, tuning::kImpulseTolerance);
    ++stats.iterative_islands;
    stats.sweeps += swept.sweeps;
    if (!swept.converged) ++stats.unconverged_sweeps;
    f = std::move(swept.f);
  }
  applyJointImpulses(world, joints, f.tail(nj));
  return f.head(nc);
}

}  // namespace tumble
