#include "dynamics/baraff/resting_forces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/baraff/collisions.h"
#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"
#include "dynamics/island_impulses.h"
#include "dynamics/joints/contact_joint_lcp.h"
#include "dynamics/joints/joint_forces.h"
#include "dynamics/joints/pd_motor.h"
#include "dynamics/row_gauss_seidel.h"

namespace tumble {
namespace {

// Acceleration of the material point at p of a body under its wrench: a + alpha x r + w x (w x r),
// with alpha = I^-1 (tau - w x I w) (Euler's equation in world axes). On a rounded piece the
// contact moves over the surface as it rolls, and follows the core point c behind it: the
// centripetal part is the core point's, w x (w x (c - x)); alpha x r keeps p's lever, so a ball
// rolling without slipping keeps its contact at rest (a + alpha x r = 0 along the ground).
Eigen::Vector3d pointAcceleration(const RigidBody& body, const Wrench& wrench, const Eigen::Vector3d& p,
                                  const Eigen::Vector3d& core) {
  if (body.is_static) return Eigen::Vector3d::Zero();
  Eigen::Vector3d r = p - body.x;
  Eigen::Vector3d w = body.angularVelocity();
  Eigen::Vector3d alpha = inverseInertiaWorld(body) * (wrench.torque - w.cross(body.L));
  return wrench.force * body.inv_mass + alpha.cross(r) + w.cross(w.cross(core - body.x));
}

double rowAcceleration(const World& world, const ContactRow& row, const std::vector<Wrench>& wrenches) {
  const RigidBody& A = world.bodies[row.a];
  const RigidBody& B = world.bodies[row.b];
  Eigen::Vector3d rel = pointAcceleration(B, wrenches[row.b], B.x + row.rb, B.x + row.cb) -
                        pointAcceleration(A, wrenches[row.a], A.x + row.ra, A.x + row.ca);
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

// The joints' rows at the acceleration level, under the applied forces and the PD motors'
// torques, for a resting solve to take with its contact rows (joints/contact_joint_lcp.h): a
// resting body may hang from a joint (a chain lying on the ground), and its contact forces are
// then those the joints allow. Velocity motors are left out (the integrator holds them); the
// joint forces found with the contacts' are dropped, since the integrator evaluates the joints
// again at each of its stages with these contact forces held. Empty in a world without joints.
struct RestingJointRows {
  std::vector<JointRow> rows;
  Eigen::VectorXd b;
};

RestingJointRows restingJointRows(const RestingContext& ctx) {
  RestingJointRows out;
  if (ctx.world.joints.empty()) return out;
  std::vector<Wrench> applied = ctx.wrenches;
  addMotorTorques(ctx.world, applied);
  jointAccelerationRows(ctx.world, applied, ctx.step_s, false, out.rows, out.b);
  return out;
}

// Pivots the contact problem p (over lcp's rows) together with the joint rows, if any; returns the
// contact rows' part of the answer.
lcp::LcpResult pivotWithJoints(const RestingContext& ctx, const ContactLcp& lcp, const lcp::LcpProblem& p,
                               const RestingJointRows& joints) {
  if (joints.rows.empty()) return solveContactLcp(p, ctx.stats);
  lcp::LcpResult joined = solveContactLcp(withJointRows(ctx.world, p, lcp.rows, joints.rows, joints.b), ctx.stats);
  joined.f.conservativeResize(p.size());
  joined.w.conservativeResize(p.size());
  return joined;
}

Eigen::Vector3d tangentialVelocity(const World& world, const Contact& c) {
  Eigen::Vector3d v = pointVelocity(world.bodies[c.b], c.point) - pointVelocity(world.bodies[c.a], c.point);
  return v - v.dot(c.normal) * c.normal;
}

// Baraff's b: the relative acceleration along each row if no contact force acted. For a normal
// between two moving bodies the normal turns with A's face, adding 2 (w_A x n) . v_rel (Baraff 1994);
// with B's face when A is rounded (a ball on a moving box's face). Between two rounded pieces the
// normal joins their cores and turns as they pass each other: the gap |c_B - c_A| - r_A - r_B
// has second derivative n . a_rel + |v_rel,t|^2 / |c_B - c_A| (the cores' relative motion).
Eigen::VectorXd freeAccelerations(const World& world, const ContactRows& rows, const std::vector<Wrench>& wrenches) {
  Eigen::VectorXd b(rows.rows.size());
  for (std::size_t r = 0; r < rows.rows.size(); ++r) b[r] = rowAcceleration(world, rows.rows[r], wrenches);
  for (int r : rows.normal_row) {
    const ContactRow& row = rows.rows[r];
    const RigidBody& A = world.bodies[row.a];
    const RigidBody& B = world.bodies[row.b];
    if (A.is_static || B.is_static) continue;
    if (row.rounded_a && row.rounded_b) {
      const Eigen::Vector3d v_cores = pointVelocity(B, B.x + row.cb) - pointVelocity(A, A.x + row.ca);
      const double apart = row.dir.dot(B.x + row.cb - A.x - row.ca);
      const Eigen::Vector3d v_t = v_cores - v_cores.dot(row.dir) * row.dir;
      if (apart > 0) b[r] += v_t.squaredNorm() / apart;
      continue;
    }
    Eigen::Vector3d v_rel = pointVelocity(B, B.x + row.rb) - pointVelocity(A, A.x + row.ra);
    const Eigen::Vector3d w_face = row.rounded_a ? B.angularVelocity() : A.angularVelocity();
    b[r] += 2 * w_face.cross(row.dir).dot(v_rel);
  }
  return b;
}

// How much a unit force along d at the contact changes the relative velocity along d:
// d . (J M^-1 J^T) d for that one row, both bodies.
double rowMobility(const World& world, const Contact& c, const Eigen::Vector3d& d) {
  double k = 0;
  for (int i : {c.a, c.b}) {
    const RigidBody& body = world.bodies[i];
    if (body.is_static) continue;
    const Eigen::Vector3d rxd = (c.point - body.x).cross(d);
    k += body.inv_mass + rxd.dot(inverseInertiaWorld(body) * rxd);
  }
  return k;
}

// A slide slower than friction can stop within one step is held by static friction instead:
// dynamic friction held over the whole step would overshoot and reverse it (a sliding block then
// chatters at about mu g dt / 2 instead of stopping). The deceleration friction can give is
// estimated from the contact's own normal load, mu times the free normal acceleration. At a
// rounded piece's one point friction also turns the body, so it slows the contact by the ratio of
// the tangential to the normal mobility more (7/2 for a ball on the ground, where a slide of
// mu g dt had gone on dynamic and reversed every step, the ball never rolling); a polyhedron's
// contacts share their load over a manifold, where one point's ratio says little, and keep 1.
bool slides(const RestingContext& ctx, const Contact& c, const Eigen::Vector3d& vt) {
  double speed = vt.norm();
  if (speed <= ctx.settings.sliding_speed_m_s) return false;
  if (ctx.step_s <= 0) return true;
  const RigidBody& A = ctx.world.bodies[c.a];
  const RigidBody& B = ctx.world.bodies[c.b];
  double load = -c.normal.dot(pointAcceleration(B, ctx.wrenches[c.b], c.point, c.point + c.radius_b * c.normal) -
                              pointAcceleration(A, ctx.wrenches[c.a], c.point, c.point - c.radius_a * c.normal));
  double gain = 1;
  if (c.radius_a > 0 || c.radius_b > 0) {
    const double normal = rowMobility(ctx.world, c, c.normal);
    if (normal > 0) gain = std::max(1.0, rowMobility(ctx.world, c, vt / speed) / normal);
  }
  return speed > gain * c.friction * std::max(0.0, load) * ctx.step_s;
}

// Static friction rows ask for the tangential velocity left at the contact to vanish within the
// step (acceleration -v_t / step_s), not merely for zero acceleration, so a slide held by static
// friction stops instead of going on at constant speed. Rows slipping slower than the sliding
// speed (contacts that stick) keep asking for zero acceleration: exact resting cases stay exact.
void stopResidualSlip(const RestingContext& ctx, const std::vector<ContactRow>& rows,
                      const std::vector<char>& is_friction, Eigen::VectorXd& b) {
  if (ctx.step_s <= 0) return;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!is_friction[r]) continue;
    double v = rowVelocity(ctx.world, rows[r]);
    if (std::abs(v) > ctx.settings.sliding_speed_m_s) b[r] += v / ctx.step_s;
  }
}

// Likewise a resting contact's normal rows ask for the normal velocity left at the contact to
// vanish within the step (acceleration -v_n / step_s), not merely for zero acceleration. The
// forces are held over the step while the bodies turn, so a pivot's normal velocity drifts by a
// little every step (second order in the step). Held at zero acceleration that drift accumulates:
// a rocking block's pivot sank step after step (each sub-step's position correction lifting it
// back and changing the energy), or lifted at a growing speed under a support that kept pushing
// (the block gaining energy until the pivot took off and landed again); its swings lost or
// gained up to 5 % between landings, against Housner's ratio (hard case 14). Asked to stop, the
// pivot stays put: every landing then keeps the ratio within 0.3 %. Where stopping a lift needs a
// pull, the force is zero and the contact separates. Rows moving slower than the sliding speed
// keep asking for zero acceleration: exact resting cases stay exact.
void stopNormalDrift(const RestingContext& ctx, const std::vector<ContactRow>& rows,
                     const std::vector<int>& normal_rows, Eigen::VectorXd& b) {
  if (ctx.step_s <= 0) return;
  for (int r : normal_rows) {
    const double v = rowVelocity(ctx.world, rows[static_cast<std::size_t>(r)]);
    if (std::abs(v) > ctx.settings.sliding_speed_m_s) b[r] += v / ctx.step_s;
  }
}

// Dynamic friction of the sliding contacts of a pivoted island: one row against each slide, the
// contact it belongs to, and its magnitude mu f_n.
struct SlideForces {
  std::vector<ContactRow> rows;
  std::vector<int> contact;
  Eigen::VectorXd g;
};

// Per contact of an island, the impulse over step_s its rows' forces give (N s on B, world axes),
// remembered so that the island starts warm if it must be solved at the velocity level next time.
void rememberForces(const RestingContext& ctx, const std::vector<const Contact*>& resting, const ContactRows& rows,
                    const Eigen::VectorXd& f, const SlideForces* slide) {
  std::vector<Eigen::Vector3d> impulse = impulsePerContact(rows, f, ctx.step_s);
  if (slide)
    for (std::size_t j = 0; j < slide->rows.size(); ++j)
      impulse[slide->contact[j]] += slide->g[j] * ctx.step_s * slide->rows[j].dir;
  for (std::size_t k = 0; k < resting.size(); ++k)
    ctx.memory->next.push_back(impulseRecord(ctx.world, *resting[k], impulse[k]));
}

// BoxedFriction: every contact gets boxed friction rows (|f_t| <= mu f_n, asking for zero
// tangential acceleration). Always bounded (A is positive semi-definite); a sliding contact is
// then held by at most mu f_n for this sub-step instead of being slowed by exactly mu f_n. Counted.
// The joints' rows are pivoted with the contacts', as in pivot().
void restWithBoxedFriction(const RestingContext& ctx, const std::vector<const Contact*>& resting) {
  ++ctx.stats.friction_fallbacks;
  ContactLcp lcp = buildContactLcp(ctx.world, resting, std::vector<char>(resting.size(), 1));
  lcp.problem.b = freeAccelerations(ctx.world, lcp, ctx.wrenches);
  std::vector<char> is_friction(lcp.rows.size(), 1);
  for (int r : lcp.normal_row) is_friction[r] = 0;
  stopResidualSlip(ctx, lcp.rows, is_friction, lcp.problem.b);
  stopNormalDrift(ctx, lcp.rows, lcp.normal_row, lcp.problem.b);
  lcp::LcpResult r = pivotWithJoints(ctx, lcp, lcp.problem, restingJointRows(ctx));
  addForces(ctx.world, lcp.rows, r.f, ctx.wrenches);
}

// AccelerationSweeps: rows (normal; two tangents for a sticking contact, one against the slide for
// a sliding one) solved by projected Gauss-Seidel on the accelerations, from zero, without forming
// A (row_gauss_seidel.h). From zero at every sub-step this does not converge on a pyramid or a pile
// within 200 sweeps, which is why large islands with a memory, and islands whose pivoting stopped
// short, go to VelocityLevel instead; this is left for a sub-step without a memory. Sliding
// friction is mu f_n against the slide, or less where that would reverse the slide within `step_s`.
// In a world with joints the joints' rows are swept with the contacts' (contact_joint_lcp.h).
void sweepAccelerations(const RestingContext& ctx, const std::vector<const Contact*>& resting) {
  ContactRows rows;   // A is never formed
  std::vector<RowLimit> limits;
  for (const Contact* c : resting) {
    if (c->friction <= 0) {
      rows.addContact(ctx.world, *c, false);
      limits.push_back({});
      continue;
    }
    Eigen::Vector3d vt = tangentialVelocity(ctx.world, *c);
    double speed = vt.norm();
    if (slides(ctx, *c, vt)) {
      rows.addSlidingContact(ctx.world, *c, -vt / speed);
      double target = ctx.step_s > 0 ? speed / ctx.step_s : std::numeric_limits<double>::infinity();
      limits.push_back({});
      limits.push_back({RowLimit::Sliding, rows.normal_row.back(), c->friction, target});
    } else {
      rows.addContact(ctx.world, *c, true);
      limits.push_back({});
      for (int t = 0; t < 2; ++t) limits.push_back({RowLimit::Static, rows.normal_row.back(), c->friction, 0});
    }
  }
  Eigen::VectorXd b = freeAccelerations(ctx.world, rows, ctx.wrenches);
  std::vector<char> is_static_friction(limits.size());
  for (std::size_t r = 0; r < limits.size(); ++r) is_static_friction[r] = limits[r].kind == RowLimit::Static;
  stopResidualSlip(ctx, rows.rows, is_static_friction, b);
  stopNormalDrift(ctx, rows.rows, rows.normal_row, b);
  const RestingJointRows joints = restingJointRows(ctx);
  if (!joints.rows.empty()) {
    // Counts its island and sweeps itself; stops where the contacts' own sweeps would.
    const Eigen::VectorXd f = sweepContactsWithJoints(ctx.world, rows, limits, b, joints.rows, joints.b, {}, ctx.stats,
                                                      RowGaussSeidelSettings{}.tolerance)
                                  .head(rows.size());
    addForces(ctx.world, rows.rows, f, ctx.wrenches);
    return;
  }
  ++ctx.stats.iterative_islands;
  RowGaussSeidelResult r = solveRowsGaussSeidel(ctx.world, rows.rows, b, limits);
  ctx.stats.sweeps += r.sweeps;
  if (!r.converged) ++ctx.stats.unconverged_sweeps;
  addForces(ctx.world, rows.rows, r.f, ctx.wrenches);
}

// The sweep cap for an island at rest (every contact's two points moving apart, together or
// sideways slower than the resting speed): a share of the square of its moving bodies' count
// (tuning::kRestingChainSweeps); 0 for an island in motion. At rest an unconverged answer shows
// as creep: the 101-stone arch's island stopped at 200 sweeps on every step and the ring crept
// down by about 0.2 mm a second; given 5000 once it converged, and then held to 0.02 mm with a few
// sweeps a step. In motion the answer changes with every step anyway, and the 100-piece pile,
// given the larger cap there as well, took 1.4 times as long.
int restingChainSweeps(const RestingContext& ctx, const std::vector<const Contact*>& island) {
  thread_local std::vector<int> bodies;
  bodies.clear();
  const double slow = ctx.settings.resting_speed_m_s;
  for (const Contact* c : island) {
    const Eigen::Vector3d v = pointVelocity(ctx.world.bodies[c->b], c->point) - pointVelocity(ctx.world.bodies[c->a], c->point);
    if (v.squaredNorm() > slow * slow) return 0;
    for (int k : {c->a, c->b})
      if (!ctx.world.bodies[k].is_static) bodies.push_back(k);
  }
  std::sort(bodies.begin(), bodies.end());
  const double n = static_cast<double>(std::unique(bodies.begin(), bodies.end()) - bodies.begin());
  return static_cast<int>(tuning::kRestingChainSweeps * n * n);
}

// VelocityLevel: the impulses p over step_s that leave no contact approaching (v_n+ >= 0) and no
// contact slipping inside its friction pyramid, given the velocities the applied forces would
// reach within step_s (island_impulses.h); the forces are p / step_s. Warm started from the
// island's impulses of the last sub-step: Gauss-Seidel started from zero at every sub-step does
// not converge on a pile or a pyramid in 200 sweeps, and the unbalanced forces it leaves make them
// creep.
//
// `resting` holds the island's resting contacts first, then (from `first_near` on) its near ones
// (addNearContacts): within the detection margin but not touching, or touching and separating.
// Their normal rows ask only that the gap not be overshot within the step, v_n+ >= -gap / step_s,
// as the time-stepping model's speculative contacts do. Without them a piece whose support opened
// by more than the contact tolerance (a micrometre, after a projection or a turn) fell freely for
// a sub-step, reached g dt = 4 cm/s and landed again. The 100-piece pile with every island solved
// here (`pivoting_max_rows` 0): at rest below 5e-5 m/s from 3.5 s with them, 7 pieces still above
// 1e-3 m/s at 5 s without (and twice the CPU time).
void solveAtVelocityLevel(const RestingContext& ctx, const std::vector<const Contact*>& resting,
                          std::size_t first_near) {
  const double step_s = ctx.step_s;
  const ContactRows rows = buildContactRows(ctx.world, resting);
  const int n = rows.size();
  Eigen::VectorXd b = freeAccelerations(ctx.world, rows, ctx.wrenches) * step_s;
  for (int r = 0; r < n; ++r) b[r] += rowVelocity(ctx.world, rows.rows[r]);
  for (std::size_t k = first_near; k < resting.size(); ++k)
    b[rows.normal_row[k]] += std::max(0.0, -resting[k]->depth) / step_s;
  std::vector<const ImpulseRecord*> last(resting.size());
  for (std::size_t k = 0; k < resting.size(); ++k)
    last[k] = ctx.memory->last.find(ctx.world, *resting[k], ImpulseMemory::kMatchRadius);
  Eigen::VectorXd impulses;
  if (ctx.world.joints.empty()) {
    IslandImpulseSettings gs;
    gs.tolerance = tuning::kImpulseTolerance;
    gs.max_sweeps = std::max(gs.max_sweeps, restingChainSweeps(ctx, resting));
    impulses = solveIslandImpulses(ctx.world, rows, resting, b, warmStart(rows, last), gs, ctx.stats).p;
  } else {
    // The joints' rows swept with the island's (joints/contact_joint_lcp.h), as pivot() takes them:
    // their velocity terms over the step are J v + (J a + J' v) step_s.
    RestingJointRows joints = restingJointRows(ctx);
    joints.b *= step_s;
    for (std::size_t j = 0; j < joints.rows.size(); ++j) joints.b[j] += jointRowVelocity(ctx.world, joints.rows[j]);
    impulses = sweepContactsWithJoints(ctx.world, rows, pyramidLimits(rows, resting), b, joints.rows, joints.b,
                                       warmStart(rows, last), ctx.stats)
                   .head(n);
  }
  const Eigen::VectorXd forces = impulses / step_s;
  addForces(ctx.world, rows.rows, forces, ctx.wrenches);
  rememberForces(ctx, resting, rows, forces, nullptr);
}

// An island whose pivoting stopped short with forces that do not satisfy the LCP.
void solveStoppedShort(const RestingContext& ctx, const std::vector<const Contact*>& resting) {
  ++ctx.stats.iterative_fallbacks;
  if (ctx.memory && ctx.step_s > 0) solveAtVelocityLevel(ctx, resting, resting.size());
  else sweepAccelerations(ctx, resting);
}

// Pivoting. Static friction joins the LCP (tangential acceleration 0 while |f_t| <= mu f_n). A
// sliding contact feels dynamic friction mu f_n against its sliding direction instead: a force
// that depends on the unknown f_n, found by fixed-point iteration on f_n (exact once f_n is
// steady). Falls back to VelocityLevel (AccelerationSweeps without a memory) when pivoting stops
// short with forces that do not satisfy the LCP, and to BoxedFriction when the iteration diverges.
// An arch's islands, split between resting and colliding contacts as its stones rock, stop short
// often (the statics of a ring of redundant face contacts are indeterminate): restarted from zero
// at every sub-step, Gauss-Seidel on the accelerations left the 25-stone arch sinking 0.29 m in
// its first second; warm-started at the velocity level, 1 cm.
//
// Whether a slide is slow enough for friction to stop within the step is first judged from the
// contact's free normal acceleration (slides()); that misses the load other bodies put on it: a
// light plate pinched under a heavy block has no free normal acceleration against it, yet the
// block's weight presses it, and dynamic friction of hundreds of newtons held over the step on an
// 80 g plate reversed its slip and spun it at rad/s. So once the forces are known, a slide that its
// own dynamic friction would stop within the step is held by static friction, and the island is
// solved again (once: `stuck` lists the contacts so held).
void pivot(const RestingContext& ctx, const std::vector<const Contact*>& resting, const std::vector<char>* stuck = nullptr) {
  const World& world = ctx.world;
  std::vector<char> sticks(resting.size(), 0);
  SlideForces slide;
  for (std::size_t i = 0; i < resting.size(); ++i) {
    Eigen::Vector3d vt = tangentialVelocity(world, *resting[i]);
    bool sliding = !(stuck && (*stuck)[i]) && slides(ctx, *resting[i], vt);
    sticks[i] = !sliding;
    if (sliding && resting[i]->friction > 0) {
      slide.rows.push_back(slideRow(world, *resting[i], -vt.normalized()));
      slide.contact.push_back(static_cast<int>(i));
    }
  }
  ContactLcp lcp = buildContactLcp(world, resting, sticks);
  Eigen::VectorXd b = freeAccelerations(world, lcp, ctx.wrenches);
  std::vector<char> is_friction(lcp.rows.size(), 1);
  for (int r : lcp.normal_row) is_friction[r] = 0;
  stopResidualSlip(ctx, lcp.rows, is_friction, b);
  stopNormalDrift(ctx, lcp.rows, lcp.normal_row, b);
  const int n = lcp.size(), m = static_cast<int>(slide.rows.size());
  Eigen::MatrixXd coupling;   // J_lcp M^-1 J_slide^T: what dynamic friction does to each row
  if (m > 0) {
    std::vector<ContactRow> all = lcp.rows;
    all.insert(all.end(), slide.rows.begin(), slide.rows.end());
    coupling = delassus(world, all).block(0, n, n, m);
  }
  slide.g = Eigen::VectorXd::Zero(m);   // dynamic friction magnitudes
  // A world with joints: the joints' rows join the island's problem (restingJointRows).
  const RestingJointRows joints = restingJointRows(ctx);
  auto solve = [&](const lcp::LcpProblem& p) { return pivotWithJoints(ctx, lcp, p, joints); };
  lcp.problem.b = b;
  lcp::LcpResult r = solve(lcp.problem);
  if (!usableLcpAnswer(r, lcp.problem)) {
    solveStoppedShort(ctx, resting);
    return;
  }
  // The iteration contracts when dynamic friction changes the normal forces less than it is
  // changed by them; where a sliding body is wedged (friction pressing it into its supports) the
  // gain exceeds 1 and the forces would grow geometrically (to 1e12 N within 8 passes, seen in the
  // pile). A change that grows is that case: give up the fixed point for this island.
  double last_change = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < tuning::kMaxDynamicFrictionPasses && m > 0; ++pass) {
    Eigen::VectorXd next(m);
    for (int k = 0; k < m; ++k)
      next[k] = resting[slide.contact[k]]->friction * std::max(0.0, r.f[lcp.normal_row[slide.contact[k]]]);
    double change = (next - slide.g).cwiseAbs().maxCoeff();
    if (pass > 0 && change > last_change) {
      restWithBoxedFriction(ctx, resting);
      return;
    }
    last_change = change;
    slide.g = next;
    if (change <= tuning::kDynamicFrictionSettled * (1 + slide.g.cwiseAbs().maxCoeff())) break;
    lcp.problem.b = b + coupling * slide.g;
    r = solve(lcp.problem);
    if (!usableLcpAnswer(r, lcp.problem)) {
      solveStoppedShort(ctx, resting);
      return;
    }
  }
  if (!stuck && m > 0 && ctx.step_s > 0) {
    auto samePair = [](const Contact& x, const Contact& y) {
      return (x.a == y.a && x.b == y.b) || (x.a == y.b && x.b == y.a);
    };
    std::vector<char> held(resting.size(), 0);
    bool any = false;
    for (int k = 0; k < m; ++k) {
      const Contact& c = *resting[slide.contact[k]];
      const Eigen::Vector3d vt = tangentialVelocity(world, c);
      const double speed = vt.norm();
      if (speed > 0 && speed <= slide.g[k] * rowMobility(world, c, vt / speed) * ctx.step_s) {
        held[slide.contact[k]] = 1;
        any = true;
      }
    }
    // A face slides as one: its corners, held one by one, would stop unequally and turn it.
    for (int k = 0; k < m && any; ++k)
      for (int j = 0; j < m; ++j)
        if (held[slide.contact[j]] && samePair(*resting[slide.contact[k]], *resting[slide.contact[j]]))
          held[slide.contact[k]] = 1;
    if (any) {
      pivot(ctx, resting, &held);
      return;
    }
  }
  addForces(world, lcp.rows, r.f, ctx.wrenches);
  if (m > 0) addForces(world, slide.rows, slide.g, ctx.wrenches);
  if (ctx.memory && ctx.step_s > 0) rememberForces(ctx, resting, lcp, r.f, &slide);
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

RestingSolve chooseRestingSolve(const std::vector<const Contact*>& island, const RestingContext& ctx) {
  if (!tooLargeToPivot(island.size(), ctx.settings.max_direct_rows)) return RestingSolve::Pivoting;
  return ctx.memory && ctx.step_s > 0 ? RestingSolve::VelocityLevel : RestingSolve::AccelerationSweeps;
}

void addRestingForces(const std::vector<Contact>& contacts, const RestingContext& ctx) {
  if (ctx.memory) ctx.memory->next.clear();
  std::vector<ContactClass> classes(contacts.size());
  std::vector<const Contact*> resting;
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if ((classes[i] = classify(ctx.world, contacts[i], ctx.settings)) == ContactClass::Resting)
      resting.push_back(&contacts[i]);
  ctx.stats.resting += static_cast<int>(resting.size());
  std::vector<std::vector<const Contact*>> islands = splitIntoIslands(ctx.world, resting);
  std::vector<RestingSolve> solve(islands.size());
  std::vector<char> at_velocity(islands.size(), 0);
  std::vector<std::size_t> first_near(islands.size());
  for (std::size_t i = 0; i < islands.size(); ++i) {
    const bool can_force = ctx.forced && (*ctx.forced != RestingSolve::VelocityLevel || (ctx.memory && ctx.step_s > 0));
    solve[i] = can_force ? *ctx.forced : chooseRestingSolve(islands[i], ctx);
    at_velocity[i] = solve[i] == RestingSolve::VelocityLevel;
    first_near[i] = islands[i].size();
  }
  // Islands solved at the velocity level take their near contacts too.
  addNearContacts(ctx.world, contacts, classes, ctx.step_s, at_velocity, islands);
  // Wrenches of one island depend only on that island's bodies, so the order is immaterial.
  for (std::size_t i = 0; i < islands.size(); ++i) {
    switch (solve[i]) {
      case RestingSolve::Pivoting: pivot(ctx, islands[i]); break;
      case RestingSolve::VelocityLevel: solveAtVelocityLevel(ctx, islands[i], first_near[i]); break;
      case RestingSolve::AccelerationSweeps: sweepAccelerations(ctx, islands[i]); break;
      case RestingSolve::BoxedFriction: restWithBoxedFriction(ctx, islands[i]); break;
    }
  }
  if (ctx.memory) ctx.memory->last.replace(std::move(ctx.memory->next));
}

}  // namespace tumble
