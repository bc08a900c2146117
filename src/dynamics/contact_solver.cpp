#include "dynamics/contact_solver.h"

#include <cmath>
#include <limits>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/contact_lcp.h"
#include "dynamics/impulse_propagation.h"
#include "dynamics/row_gauss_seidel.h"

namespace tumble {
namespace {

bool touching(const Contact& c, const ContactSettings& s) { return c.depth >= -s.tolerance_m; }

}  // namespace

ContactClass classify(const World& world, const Contact& c, const ContactSettings& s) {
  if (!touching(c, s)) return ContactClass::Separating;
  double vn = normalVelocity(world, c);
  if (vn < -s.resting_speed_m_s) return ContactClass::Colliding;
  if (vn > s.resting_speed_m_s) return ContactClass::Separating;
  return ContactClass::Resting;
}

bool resolveCollisions(World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                       double min_bounce_speed, ContactSolveStats& stats) {
  // Every touching contact takes part, resting ones too: an impact is passed on through what it
  // presses against. Islands are independent; within one, impulse_propagation.h says how the
  // impact travels pair by pair while each pair's points are solved together.
  std::vector<const Contact*> set;
  bool any = false;
  for (const Contact& c : contacts) {
    ContactClass k = classify(world, c, s);
    if (k == ContactClass::Separating) continue;
    any |= k == ContactClass::Colliding;
    stats.colliding += k == ContactClass::Colliding;
    set.push_back(&c);
  }
  if (!any) return false;
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, set))
    propagateImpulses(world, island, s, min_bounce_speed, stats);
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

// A slide slower than friction can stop within one step is held by static friction instead:
// dynamic friction held over the whole step would overshoot and reverse it (a sliding block then
// chatters at about mu g dt / 2 instead of stopping). The deceleration friction can give is
// estimated from the contact's own normal load, mu times the free normal acceleration.
bool slides(const World& world, const Contact& c, const Wrench& wa, const Wrench& wb, const ContactSettings& s,
            double step_s, const Eigen::Vector3d& vt) {
  double speed = vt.norm();
  if (speed <= s.sliding_speed_m_s) return false;
  if (step_s <= 0) return true;
  const RigidBody& A = world.bodies[c.a];
  const RigidBody& B = world.bodies[c.b];
  double load = -c.normal.dot(pointAcceleration(B, wb, c.point) - pointAcceleration(A, wa, c.point));
  return speed > c.friction * std::max(0.0, load) * step_s;
}

// Static friction rows ask for the tangential velocity left at the contact to vanish within the
// step (acceleration -v_t / step_s), not merely for zero acceleration, so a slide held by static
// friction stops instead of going on at constant speed. Rows slipping slower than the sliding
// speed (contacts that stick) keep asking for zero acceleration: exact resting cases stay exact.
void stopResidualSlip(const World& world, const std::vector<ContactRow>& rows, const std::vector<char>& is_friction,
                      const ContactSettings& s, double step_s, Eigen::VectorXd& b) {
  if (step_s <= 0) return;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!is_friction[r]) continue;
    double v = rowVelocity(world, rows[r]);
    if (std::abs(v) > s.sliding_speed_m_s) b[r] += v / step_s;
  }
}

// The fallback when dynamic friction cannot be found by iteration: every contact gets boxed
// friction rows (|f_t| <= mu f_n, asking for zero tangential acceleration), as ODE and Bullet treat
// all contacts. Always bounded (A is positive semi-definite); a sliding contact is then held by
// at most mu f_n for this sub-step instead of being slowed by exactly mu f_n. Counted.
void restWithBoxedFriction(const World& world, const std::vector<const Contact*>& resting,
                           const ContactSettings& s, double step_s,
                           std::vector<Wrench>& wrenches, ContactSolveStats& stats) {
  ++stats.friction_fallbacks;
  ContactLcp lcp = buildContactLcp(world, resting, std::vector<char>(resting.size(), 1));
  lcp.problem.b = freeAccelerations(world, lcp, wrenches);
  std::vector<char> is_friction(lcp.rows.size(), 1);
  for (int r : lcp.normal_row) is_friction[r] = 0;
  stopResidualSlip(world, lcp.rows, is_friction, s, step_s, lcp.problem.b);
  lcp::LcpResult r = solveContactLcp(lcp.problem, stats);
  addForces(world, lcp.rows, r.f, wrenches);
}

// Rows (normal; two tangents for a sticking contact, one against the slide for a sliding one)
// solved by projected Gauss-Seidel on the accelerations, from zero, without forming A
// (row_gauss_seidel.h): the fallback when pivoting stops short, and for large islands without a
// memory. With a memory (the pipeline's calls) large islands get restIslandAtVelocityLevel
// instead: from zero at every sub-step this does not converge on a pyramid or a pile within 200
// sweeps. (Routing the stopped-short fallbacks there too was tried: it moved the domino wave
// speed by several percent between runs and made the pile slower; not kept.) Sliding friction is
// mu f_n against the slide, or less where that would reverse the slide within `step_s`.
void restIslandIteratively(const World& world, const std::vector<const Contact*>& resting,
                           const ContactSettings& s, double step_s, std::vector<Wrench>& wrenches,
                           ContactSolveStats& stats) {
  ++stats.iterative_islands;
  ContactLcp lcp;   // rows and normal_row only: A is never formed
  std::vector<RowLimit> limits;
  for (const Contact* c : resting) {
    int normal = static_cast<int>(lcp.rows.size());
    lcp.normal_row.push_back(normal);
    lcp.rows.push_back(rowAlong(world, *c, c->normal));
    limits.push_back({});
    if (c->friction <= 0) continue;
    Eigen::Vector3d vt = tangentialVelocity(world, *c);
    double speed = vt.norm();
    if (slides(world, *c, wrenches[c->a], wrenches[c->b], s, step_s, vt)) {
      lcp.rows.push_back(rowAlong(world, *c, -vt / speed));
      double target = step_s > 0 ? speed / step_s : std::numeric_limits<double>::infinity();
      limits.push_back({RowLimit::Sliding, normal, c->friction, target});
    } else {
      Eigen::Vector3d t1, t2;
      tangentsOf(c->normal, t1, t2);
      for (const Eigen::Vector3d& t : {t1, t2}) {
        lcp.rows.push_back(rowAlong(world, *c, t));
        limits.push_back({RowLimit::Static, normal, c->friction, 0});
      }
    }
  }
  Eigen::VectorXd b = freeAccelerations(world, lcp, wrenches);
  std::vector<char> is_static_friction(limits.size());
  for (std::size_t r = 0; r < limits.size(); ++r) is_static_friction[r] = limits[r].kind == RowLimit::Static;
  stopResidualSlip(world, lcp.rows, is_static_friction, s, step_s, b);
  RowGaussSeidelResult r = solveRowsGaussSeidel(world, lcp.rows, b, limits);
  stats.sweeps += r.sweeps;
  if (!r.converged) ++stats.unconverged_sweeps;
  addForces(world, lcp.rows, r.f, wrenches);
}

// The rows [first, end) of contact k in buildContactLcp's layout (its normal row, then its friction rows).
std::pair<int, int> rowsOfContact(const ContactLcp& lcp, std::size_t k) {
  const int end = k + 1 < lcp.normal_row.size() ? lcp.normal_row[k + 1] : static_cast<int>(lcp.rows.size());
  return {lcp.normal_row[k], end};
}

// Per contact of an island, the impulse over step_s its rows' forces give (N s on B, world axes),
// remembered so that the island starts warm if it must be solved iteratively next time.
void rememberForces(const World& world, const std::vector<const Contact*>& resting, const ContactLcp& lcp,
                    const Eigen::VectorXd& f, const std::vector<ContactRow>& extra_rows,
                    const std::vector<int>& extra_contact, const Eigen::VectorXd& extra_f, double step_s,
                    RestingMemory& memory) {
  std::vector<Eigen::Vector3d> impulse(resting.size(), Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < resting.size(); ++k) {
    auto [r0, r_end] = rowsOfContact(lcp, k);
    for (int r = r0; r < r_end; ++r) impulse[k] += f[r] * step_s * lcp.rows[r].dir;
  }
  for (std::size_t j = 0; j < extra_rows.size(); ++j) impulse[extra_contact[j]] += extra_f[j] * step_s * extra_rows[j].dir;
  for (std::size_t k = 0; k < resting.size(); ++k) {
    ImpulseRecord rec;
    rec.a = resting[k]->a;
    rec.b = resting[k]->b;
    rec.local = ImpulseMemory::localPoint(world, *resting[k]);
    rec.impulse = impulse[k];
    memory.next.push_back(rec);
  }
}

// An island too large to pivot, solved at the velocity level over the step (as the time-stepping
// model solves every island): the impulses p that leave no contact approaching (v_n+ >= 0) and
// no contact slipping inside its friction pyramid (v_t+ = 0, |p_t| <= mu p_n), given the
// velocities the applied forces would reach within step_s; the forces are p / step_s. Warm
// started from the island's impulses of the last sub-step (matched by pair of bodies and point):
// Gauss-Seidel started from zero at every sub-step does not converge on a pile or a pyramid in
// 200 sweeps, and the unbalanced forces it leaves make them creep.
//
// `resting` holds the island's resting contacts first, then (from `first_near` on) its near ones
// (addNearContacts): within the detection margin but not touching, or touching and separating.
// Their normal rows ask only that the gap not be overshot within the step, v_n+ >= -gap / step_s,
// as the time-stepping model's speculative contacts do. Without them a piece whose support opened
// by more than the contact tolerance (a micrometre, after a projection or a turn) fell freely for
// a sub-step, reached g dt = 4 cm/s and landed again. The 100-piece pile with every island solved
// here (`pivoting_max_rows` 0): at rest below 5e-5 m/s from 3.5 s with them, 7 pieces still above
// 1e-3 m/s at 5 s without (and twice the CPU time).
void restIslandAtVelocityLevel(const World& world, const std::vector<const Contact*>& resting,
                               std::size_t first_near, double step_s, std::vector<Wrench>& wrenches,
                               ContactSolveStats& stats, RestingMemory& memory) {
  ++stats.iterative_islands;
  ContactLcp lcp;   // rows and normal_row only: A is never formed
  std::vector<RowLimit> limits;
  for (const Contact* c : resting) {
    const int normal = static_cast<int>(lcp.rows.size());
    lcp.normal_row.push_back(normal);
    lcp.rows.push_back(rowAlong(world, *c, c->normal));
    limits.push_back({});
    if (c->friction <= 0) continue;
    Eigen::Vector3d t1, t2;
    tangentsOf(c->normal, t1, t2);
    for (const Eigen::Vector3d& t : {t1, t2}) {
      lcp.rows.push_back(rowAlong(world, *c, t));
      limits.push_back({RowLimit::Static, normal, c->friction, 0});
    }
  }
  const int n = static_cast<int>(lcp.rows.size());
  Eigen::VectorXd b = freeAccelerations(world, lcp, wrenches) * step_s;
  for (int r = 0; r < n; ++r) b[r] += rowVelocity(world, lcp.rows[r]);
  for (std::size_t k = first_near; k < resting.size(); ++k)
    b[lcp.normal_row[k]] += std::max(0.0, -resting[k]->depth) / step_s;
  Eigen::VectorXd start = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < resting.size(); ++k) {
    const ImpulseRecord* last = memory.last.find(world, *resting[k], ImpulseMemory::kMatchRadius);
    if (!last) continue;
    auto [r0, r_end] = rowsOfContact(lcp, k);
    for (int r = r0; r < r_end; ++r) start[r] = last->impulse.dot(lcp.rows[r].dir);
    start[r0] = std::max(0.0, start[r0]);
  }
  RowGaussSeidelSettings gs;
  gs.tolerance = 1e-6;   // of the largest velocity term, as for the time-stepping model's large islands
  RowGaussSeidelResult r = solveRowsGaussSeidel(world, lcp.rows, b, limits, gs, start);
  stats.sweeps += r.sweeps;
  if (!r.converged) ++stats.unconverged_sweeps;
  const Eigen::VectorXd forces = r.f / step_s;
  addForces(world, lcp.rows, forces, wrenches);
  rememberForces(world, resting, lcp, forces, {}, {}, {}, step_s, memory);
}

bool tooLargeToPivot(const std::vector<const Contact*>& island, const ContactSettings& s) {
  return 3 * island.size() > static_cast<std::size_t>(s.max_direct_rows);
}

void restIsland(const World& world, const std::vector<const Contact*>& resting, const ContactSettings& s,
                double step_s, std::vector<Wrench>& wrenches, ContactSolveStats& stats, RestingMemory* memory) {
  // Pivoting costs the cube of the rows; past max_direct_rows the iterative solve takes over (on
  // the accelerations: with a memory it is addRestingForces that solves such islands).
  if (tooLargeToPivot(resting, s)) {
    restIslandIteratively(world, resting, s, step_s, wrenches, stats);
    return;
  }
  // A pivoting solve that stops short (pivot or friction-pass cap) with forces that do not satisfy
  // the LCP would be used as it is; the iterative solve replaces it then (bounded forces).
  auto unusable = [](const lcp::LcpResult& r, const lcp::LcpProblem& p) {
    if (r.status == lcp::LcpStatus::Solved) return false;
    if (!r.f.allFinite()) return true;
    return !(r.residual.complementarity <= 1e-6 * (p.b.lpNorm<Eigen::Infinity>() + 1));
  };
  // Static friction joins the LCP (tangential acceleration 0 while |f_t| <= mu f_n). A sliding
  // contact feels dynamic friction mu f_n against its sliding direction instead: a force that
  // depends on the unknown f_n, found by fixed-point iteration on f_n (exact once f_n is steady).
  std::vector<char> sticks(resting.size(), 0);
  std::vector<ContactRow> slide_rows;
  std::vector<int> slide_contact;
  for (std::size_t i = 0; i < resting.size(); ++i) {
    Eigen::Vector3d vt = tangentialVelocity(world, *resting[i]);
    const Contact& c = *resting[i];
    bool sliding = slides(world, c, wrenches[c.a], wrenches[c.b], s, step_s, vt);
    sticks[i] = !sliding;
    if (sliding && resting[i]->friction > 0) {
      slide_rows.push_back(rowAlong(world, *resting[i], -vt.normalized()));
      slide_contact.push_back(static_cast<int>(i));
    }
  }
  ContactLcp lcp = buildContactLcp(world, resting, sticks);
  Eigen::VectorXd b = freeAccelerations(world, lcp, wrenches);
  std::vector<char> is_friction(lcp.rows.size(), 1);
  for (int r : lcp.normal_row) is_friction[r] = 0;
  stopResidualSlip(world, lcp.rows, is_friction, s, step_s, b);
  const int n = static_cast<int>(lcp.rows.size()), m = static_cast<int>(slide_rows.size());
  Eigen::MatrixXd coupling;   // J_lcp M^-1 J_slide^T: what dynamic friction does to each row
  if (m > 0) {
    std::vector<ContactRow> all = lcp.rows;
    all.insert(all.end(), slide_rows.begin(), slide_rows.end());
    coupling = delassus(world, all).block(0, n, n, m);
  }
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m);   // dynamic friction magnitudes
  lcp.problem.b = b;
  lcp::LcpResult r = solveContactLcp(lcp.problem, stats);
  if (unusable(r, lcp.problem)) {
    ++stats.iterative_fallbacks;
    restIslandIteratively(world, resting, s, step_s, wrenches, stats);
    return;
  }
  // The iteration contracts when dynamic friction changes the normal forces less than it is
  // changed by them; where a sliding body is wedged (friction pressing it into its supports) the
  // gain exceeds 1 and the forces would grow geometrically (to 1e12 N within 8 passes, seen in the
  // pile). A change that grows is that case: give up the fixed point for this island.
  double last_change = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < 8 && m > 0; ++pass) {
    Eigen::VectorXd next(m);
    for (int k = 0; k < m; ++k)
      next[k] = resting[slide_contact[k]]->friction * std::max(0.0, r.f[lcp.normal_row[slide_contact[k]]]);
    double change = (next - g).cwiseAbs().maxCoeff();
    if (pass > 0 && change > last_change) {
      restWithBoxedFriction(world, resting, s, step_s, wrenches, stats);
      return;
    }
    last_change = change;
    g = next;
    if (change <= 1e-12 * (1 + g.cwiseAbs().maxCoeff())) break;
    lcp.problem.b = b + coupling * g;
    r = solveContactLcp(lcp.problem, stats);
    if (unusable(r, lcp.problem)) {
      ++stats.iterative_fallbacks;
      restIslandIteratively(world, resting, s, step_s, wrenches, stats);
      return;
    }
  }
  addForces(world, lcp.rows, r.f, wrenches);
  if (m > 0) addForces(world, slide_rows, g, wrenches);
  if (memory && step_s > 0) rememberForces(world, resting, lcp, r.f, slide_rows, slide_contact, g, step_s, *memory);
}

// Near contacts: within the detection margin but not resting (apart by more than the contact
// tolerance, or touching and separating), and not closing by their own velocity within the step
// (an impact to come is back-stepping's and the impulses'). Each is appended to the island, solved
// at the velocity level (`at_velocity`), that its moving bodies belong to; one whose bodies belong
// to two islands, or to none, is left out, so that no two solves share a body.
void addNearContacts(const World& world, const std::vector<Contact>& contacts,
                     const std::vector<ContactClass>& classes, double step_s, const std::vector<char>& at_velocity,
                     std::vector<std::vector<const Contact*>>& islands) {
  constexpr int kFixed = -2;   // a static body: belongs to every island
  std::vector<int> island_of(world.bodies.size(), -1);
  bool any = false;
  for (std::size_t i = 0; i < islands.size(); ++i) {
    if (!at_velocity[i]) continue;
    any = true;
    for (const Contact* c : islands[i])
      for (int body : {c->a, c->b}) island_of[body] = static_cast<int>(i);
  }
  if (!any) return;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    if (classes[i] != ContactClass::Separating) continue;
    if (std::max(0.0, -c.depth) + normalVelocity(world, c) * step_s < 0) continue;   // an impact to come
    const int ia = world.bodies[c.a].is_static ? kFixed : island_of[c.a];
    const int ib = world.bodies[c.b].is_static ? kFixed : island_of[c.b];
    const int island = std::max(ia, ib);
    if (island >= 0 && (ia == island || ia == kFixed) && (ib == island || ib == kFixed)) islands[island].push_back(&c);
  }
}

}  // namespace

void addRestingForces(const World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                      std::vector<Wrench>& wrenches, ContactSolveStats& stats, double step_s,
                      RestingMemory* memory) {
  if (memory) memory->next.clear();
  std::vector<ContactClass> classes(contacts.size());
  std::vector<const Contact*> resting;
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if ((classes[i] = classify(world, contacts[i], s)) == ContactClass::Resting) resting.push_back(&contacts[i]);
  stats.resting += static_cast<int>(resting.size());
  std::vector<std::vector<const Contact*>> islands = splitIntoIslands(world, resting);
  // Islands too large to pivot are solved at the velocity level, warm-started, when there is a
  // memory to start from, and with their near contacts appended.
  const bool by_velocity = memory && step_s > 0;
  std::vector<char> at_velocity(islands.size(), 0);
  for (std::size_t i = 0; i < islands.size(); ++i) at_velocity[i] = by_velocity && tooLargeToPivot(islands[i], s);
  std::vector<std::size_t> first_near(islands.size());
  for (std::size_t i = 0; i < islands.size(); ++i) first_near[i] = islands[i].size();
  addNearContacts(world, contacts, classes, step_s, at_velocity, islands);
  // Wrenches of one island depend only on that island's bodies, so the order is immaterial.
  for (std::size_t i = 0; i < islands.size(); ++i) {
    if (at_velocity[i])
      restIslandAtVelocityLevel(world, islands[i], first_near[i], step_s, wrenches, stats, *memory);
    else
      restIsland(world, islands[i], s, step_s, wrenches, stats, memory);
  }
  if (memory) memory->last.replace(std::move(memory->next));
}

}  // namespace tumble
