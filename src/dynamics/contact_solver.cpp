#include "dynamics/contact_solver.h"

#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"

namespace tumble {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool touching(const Contact& c, const ContactSettings& s) { return c.depth >= -s.tolerance_m; }

double normalVelocity(const World& world, const Contact& c) {
  return rowVelocity(world, rowAlong(world, c, c.normal));
}

// The rows of an LCP over a set of contacts: one normal row per contact, followed (when the
// contact has friction) by two tangent rows bounded by +-mu times that normal variable.
struct ContactLcp {
  std::vector<ContactRow> rows;
  lcp::LcpProblem problem;
  std::vector<int> normal_row;   // per contact: its normal row
};

// `friction[i]` says whether contact i gets friction rows.
ContactLcp buildRows(const World& world, const std::vector<const Contact*>& set,
                     const std::vector<char>& friction) {
  ContactLcp out;
  std::vector<int> friction_of;
  std::vector<double> mu;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const Contact* c = set[i];
    out.normal_row.push_back(static_cast<int>(out.rows.size()));
    out.rows.push_back(rowAlong(world, *c, c->normal));
    friction_of.push_back(-1);
    mu.push_back(0);
    if (friction[i] && c->friction > 0) {
      Eigen::Vector3d t1, t2;
      tangentsOf(c->normal, t1, t2);
      for (const Eigen::Vector3d& t : {t1, t2}) {
        out.rows.push_back(rowAlong(world, *c, t));
        friction_of.push_back(out.normal_row.back());
        mu.push_back(c->friction);
      }
    }
  }
  const int n = static_cast<int>(out.rows.size());
  out.problem.A = delassus(world, out.rows);
  out.problem.b = Eigen::VectorXd::Zero(n);
  out.problem.lo = Eigen::VectorXd::Zero(n);
  out.problem.hi = Eigen::VectorXd::Constant(n, kInf);
  out.problem.friction_of = friction_of;
  out.problem.mu = Eigen::Map<Eigen::VectorXd>(mu.data(), n);
  return out;
}

lcp::LcpResult solve(const lcp::LcpProblem& p, ContactSolveStats& stats) {
  // Redundant contacts (four corners of a face) leave the split of the normal force between them
  // free, so the friction bounds +-mu f_n need not settle to the last bit between passes: settle to
  // 1e-9 of the largest bound (far below any force that moves a body measurably).
  lcp::DantzigSettings settings;
  settings.friction_tolerance = 1e-9;
  settings.max_friction_passes = 12;
  lcp::LcpResult r = lcp::solveDantzig(p, settings);
  stats.pivots += r.iterations;
  if (r.status != lcp::LcpStatus::Solved) ++stats.failures;
  return r;
}

}  // namespace

ContactClass classify(const World& world, const Contact& c, const ContactSettings& s) {
  if (!touching(c, s)) return ContactClass::Separating;
  double vn = normalVelocity(world, c);
  if (vn < -s.resting_speed_m_s) return ContactClass::Colliding;
  if (vn > s.resting_speed_m_s) return ContactClass::Separating;
  return ContactClass::Resting;
}

namespace {

// Solves Newton's law for one island of touching contacts (see resolveCollisions).
void collideIsland(World& world, const std::vector<const Contact*>& set, const ContactSettings& s,
                   double min_bounce_speed, ContactSolveStats& stats) {
  std::vector<double> vn, e;
  bool any = false;
  for (const Contact* c : set) {
    vn.push_back(normalVelocity(world, *c));
    bool colliding = vn.back() < -s.resting_speed_m_s;
    any |= colliding;
    stats.colliding += colliding;
    e.push_back(colliding && vn.back() < -min_bounce_speed ? c->restitution : 0.0);
  }
  if (!any) return;
  ContactLcp lcp = buildRows(world, set, std::vector<char>(set.size(), 1));
  for (std::size_t r = 0; r < lcp.rows.size(); ++r) lcp.problem.b[r] = rowVelocity(world, lcp.rows[r]);
  for (std::size_t i = 0; i < set.size(); ++i) lcp.problem.b[lcp.normal_row[i]] = (1 + e[i]) * vn[i];
  lcp::LcpResult r = solve(lcp.problem, stats);
  applyAlongRows(world, lcp.rows, r.f);
}

}  // namespace

bool resolveCollisions(World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                       double min_bounce_speed, ContactSolveStats& stats) {
  // Newton's law per contact: v+ >= -e v-, j >= 0, (v+ + e v-) j = 0. Written as an LCP in the
  // impulses j: w = A j + (1 + e) v-. Touching contacts that rest take part with e = 0, so an
  // impact is passed on through what it presses against. Friction rows ask for zero tangential
  // velocity after the impact, with |j_t| <= mu j_n (Coulomb on impulses).
  std::vector<const Contact*> set;
  bool any = false;
  for (const Contact& c : contacts) {
    ContactClass k = classify(world, c, s);
    if (k == ContactClass::Separating) continue;
    any |= k == ContactClass::Colliding;
    set.push_back(&c);
  }
  if (!any) return false;
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, set))
    collideIsland(world, island, s, min_bounce_speed, stats);
  return true;
}

namespace {

// Acceleration of the material point at p of a body under its wrench: a + alpha x r + w x (w x r),
// with alpha = I^-1 (tau - w x I w) (Euler's equation in world axes).
Eigen::Vector3d pointAcceleration(const RigidBody& body, const Wrench& wrench, const Eigen::Vector3d& p) {
  if (body.is_static) return Eigen::Vector3d::Zero();
  Eigen::Vector3d r = p - body.x;
  Eigen::Vector3d w = body.angularVelocity();
  Eigen::Vector3d alpha = inverseInertiaWorld(body) * (wrench.torque - w.cross(body.L));
  return wrench.force * body.inv_mass + alpha.cross(r) + w.cross(w.cross(r));
}

double rowAcceleration(const World& world, const ContactRow& row, const std::vector<Wrench>& wrenches) {
  const RigidBody& A = world.bodies[row.a];
  const RigidBody& B = world.bodies[row.b];
  Eigen::Vector3d rel = pointAcceleration(B, wrenches[row.b], B.x + row.rb) -
                        pointAcceleration(A, wrenches[row.a], A.x + row.ra);
  return row.dir.dot(rel);
}

void addForces(const World& world, const std::vector<ContactRow>& rows, const Eigen::VectorXd& f,
               std::vector<Wrench>& wrenches) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ContactRow& r = rows[i];
    Eigen::Vector3d push = f[i] * r.dir;
    if (!world.bodies[r.b].is_static) {
      wrenches[r.b].force += push;
      wrenches[r.b].torque += r.rb.cross(push);
    }
    if (!world.bodies[r.a].is_static) {
      wrenches[r.a].force -= push;
      wrenches[r.a].torque -= r.ra.cross(push);
    }
  }
}

Eigen::Vector3d tangentialVelocity(const World& world, const Contact& c) {
  Eigen::Vector3d v = pointVelocity(world.bodies[c.b], c.point) - pointVelocity(world.bodies[c.a], c.point);
  return v - v.dot(c.normal) * c.normal;
}

// Baraff's b: the relative acceleration along each row if no contact force acted. For a normal
// between two moving bodies the normal turns with A's face, adding 2 (w_A x n) . v_rel (seed 002).
Eigen::VectorXd freeAccelerations(const World& world, const ContactLcp& lcp,
                                  const std::vector<Wrench>& wrenches) {
  Eigen::VectorXd b(lcp.rows.size());
  for (std::size_t r = 0; r < lcp.rows.size(); ++r) b[r] = rowAcceleration(world, lcp.rows[r], wrenches);
  for (int r : lcp.normal_row) {
    const ContactRow& row = lcp.rows[r];
    const RigidBody& A = world.bodies[row.a];
    const RigidBody& B = world.bodies[row.b];
    if (A.is_static || B.is_static) continue;
    Eigen::Vector3d v_rel = pointVelocity(B, B.x + row.rb) - pointVelocity(A, A.x + row.ra);
    b[r] += 2 * A.angularVelocity().cross(row.dir).dot(v_rel);
  }
  return b;
}

void restIsland(const World& world, const std::vector<const Contact*>& resting, const ContactSettings& s,
                std::vector<Wrench>& wrenches, ContactSolveStats& stats) {
  // Static friction joins the LCP (tangential acceleration 0 while |f_t| <= mu f_n). A sliding
  // contact feels dynamic friction mu f_n against its sliding direction instead: a force that
  // depends on the unknown f_n, found by fixed-point iteration on f_n (exact once f_n is steady).
  std::vector<char> sticks(resting.size(), 0);
  std::vector<ContactRow> slide_rows;
  std::vector<int> slide_contact;
  for (std::size_t i = 0; i < resting.size(); ++i) {
    Eigen::Vector3d vt = tangentialVelocity(world, *resting[i]);
    bool sliding = vt.norm() > s.sliding_speed_m_s;
    sticks[i] = !sliding;
    if (sliding && resting[i]->friction > 0) {
      slide_rows.push_back(rowAlong(world, *resting[i], -vt.normalized()));
      slide_contact.push_back(static_cast<int>(i));
    }
  }
  ContactLcp lcp = buildRows(world, resting, sticks);
  Eigen::VectorXd b = freeAccelerations(world, lcp, wrenches);
  const int n = static_cast<int>(lcp.rows.size()), m = static_cast<int>(slide_rows.size());
  Eigen::MatrixXd coupling;   // J_lcp M^-1 J_slide^T: what dynamic friction does to each row
  if (m > 0) {
    std::vector<ContactRow> all = lcp.rows;
    all.insert(all.end(), slide_rows.begin(), slide_rows.end());
    coupling = delassus(world, all).block(0, n, n, m);
  }
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m);   // dynamic friction magnitudes
  lcp.problem.b = b;
  lcp::LcpResult r = solve(lcp.problem, stats);
  for (int pass = 0; pass < 8 && m > 0; ++pass) {
    Eigen::VectorXd next(m);
    for (int k = 0; k < m; ++k)
      next[k] = resting[slide_contact[k]]->friction * std::max(0.0, r.f[lcp.normal_row[slide_contact[k]]]);
    double change = (next - g).cwiseAbs().maxCoeff();
    g = next;
    if (change <= 1e-12 * (1 + g.cwiseAbs().maxCoeff())) break;
    lcp.problem.b = b + coupling * g;
    r = solve(lcp.problem, stats);
  }
  addForces(world, lcp.rows, r.f, wrenches);
  if (m > 0) addForces(world, slide_rows, g, wrenches);
}

}  // namespace

void addRestingForces(const World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                      std::vector<Wrench>& wrenches, ContactSolveStats& stats) {
  std::vector<const Contact*> resting;
  for (const Contact& c : contacts)
    if (classify(world, c, s) == ContactClass::Resting) resting.push_back(&c);
  stats.resting += static_cast<int>(resting.size());
  // Wrenches of one island depend only on that island's bodies, so the order is immaterial.
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, resting))
    restIsland(world, island, s, wrenches, stats);
}

}  // namespace tumble
