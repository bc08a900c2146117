#include "dynamics/joints/contact_joint_lcp.h"

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

lcp::LcpProblem withJointRows(const World& world, const lcp::LcpProblem& contacts,
                              const std::vector<ContactRow>& contact_rows, const std::vector<JointRow>& joints,
                              const Eigen::VectorXd& joint_b) {
  const int nc = contacts.size(), nj = static_cast<int>(joints.size()), n = nc + nj;
  // Contact rows first, so the friction rows' normal indices (findex) stay as they are.
  std::vector<JointRow> all;
  all.reserve(n);
  for (const ContactRow& row : contact_rows) all.push_back(asGenericRow(row));
  all.insert(all.end(), joints.begin(), joints.end());
  lcp::LcpProblem p;
  p.A = jointDelassus(world, all);
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

Eigen::VectorXd solveContactsWithJoints(World& world, const ContactLcp& contacts, const std::vector<JointRow>& joints,
                                        const Eigen::VectorXd& joint_b, ContactSolveStats& stats) {
  const int nc = contacts.size(), nj = static_cast<int>(joints.size());
  const lcp::LcpProblem p = withJointRows(world, contacts.problem, contacts.rows, joints, joint_b);
  lcp::LcpResult r = solveContactLcp(p, stats);
  if (!usableLcpAnswer(r, p)) {
    // No usable answer (a wedged, inconsistent set): the joints alone, then no contact impulse
    // from this solve; the next step's contacts and the projections take it from there.
    ++stats.iterative_fallbacks;
    applyJointImpulses(world, joints, solveJointRows(joints, jointDelassus(world, joints), joint_b));
    return Eigen::VectorXd::Zero(nc);
  }
  applyJointImpulses(world, joints, r.f.tail(nj));
  return r.f.head(nc);
}

}  // namespace tumble
