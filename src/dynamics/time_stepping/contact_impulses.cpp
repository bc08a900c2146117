#include "dynamics/time_stepping/contact_impulses.h"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"
#include "dynamics/island_impulses.h"
#include "dynamics/joints/contact_joint_lcp.h"
#include "dynamics/joints/joint_impulses.h"
#include "dynamics/parallel_for.h"
#include "dynamics/scratch_vector.h"

namespace tumble {

namespace {

// The share of the kinetic energy an answer with bounces may add before they are dropped
// (rounding: a perfectly elastic bounce keeps it to about 1e-15).
constexpr double kBounceEnergySlack = 1e-9;

// Heaviest over lightest moving body of an island (kSweepsMassRatio).
double massRatio(const World& world, std::span<const Contact* const> island) {
  double lightest = INFINITY, heaviest = 0;
  for (const Contact* c : island)
    for (int k : {c->a, c->b}) {
      const RigidBody& body = world.bodies[k];
      if (body.is_static) continue;
      lightest = std::min(lightest, body.mass);
      heaviest = std::max(heaviest, body.mass);
    }
  return heaviest > 0 ? heaviest / lightest : 1;
}

double kineticEnergyOf(const World& world) {
  double e = 0;
  for (const RigidBody& b : world.bodies)
    if (!b.is_static) e += b.kineticEnergy();
  return e;
}

}  // namespace

// What one island's solve needs, kept between steps on each thread (islands may be solved on
// several): grown to the largest island seen, then reused.
struct ContactImpulses::IslandScratch {
  ContactRows rows;
  std::vector<const ImpulseRecord*> last;
  ScratchVector b, p;
  ContactLcp exact;          // a small island's pivoting problem
  lcp::LcpResult pivoted;
};

void ContactImpulses::prepare(const World& world, const std::vector<Contact>& contacts, const std::vector<double>& approach,
                              const StepSettings& settings, const BounceThreshold& min_bounce_speed) {
  const std::size_t m = contacts.size();
  last_.assign(m, nullptr);
  owed_.assign(m, 0);
  bounce_.assign(m, -1);
  impact_impulse_.assign(m, Eigen::Vector3d::Zero());
  all_.assign(m, nullptr);
  // Per contact, on the threads: last step's impulse (a search of the memory) and the impacts.
  parallelFor(settings.threads, m, [&](std::size_t i) {
    const Contact& c = contacts[i];
    all_[i] = &c;
    last_[i] = memory_.find(world, c, ImpulseMemory::kMatchRadius);
    owed_[i] = last_[i] && last_[i]->landing_carried <= kOwedBounceCarries ? last_[i]->landing_speed : 0;
    const double u = std::max(approach[i], owed_[i]);
    if (-c.depth <= settings.contact.tolerance_m && u > min_bounce_speed.along(c.normal)) bounce_[i] = c.restitution * u;
  });
  impacts_ = std::any_of(bounce_.begin(), bounce_.end(), [](double e) { return e >= 0; });
  islands_split_ = false;
}

void ContactImpulses::targets(const std::vector<Contact>& contacts, double dt, bool bounces) {
  want_.resize(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    want_[i] = -std::max(-contacts[i].depth, 0.0) / dt;
    if (bounces && bounce_[i] >= 0) want_[i] = std::max(want_[i], bounce_[i]);
  }
}

void ContactImpulses::cacheVelocities(const World& world) {
  // Each body's velocity once (the rows need it twice each; computing omega costs a rotation).
  velocity_.resize(world.bodies.size());
  spin_.resize(world.bodies.size());
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    const RigidBody& body = world.bodies[k];
    velocity_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.velocity();
    spin_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.angularVelocity();
  }
}

void ContactImpulses::velocityTerms(std::span<const Contact* const> set, const ContactRows& rows, const Contact* first,
                                    Eigen::Ref<Eigen::VectorXd> b) const {
  for (int r = 0; r < rows.size(); ++r) {
    const ContactRow& row = rows.rows[r];
    b[r] = row.dir.dot(velocity_[row.b] + spin_[row.b].cross(row.rb) - velocity_[row.a] - spin_[row.a].cross(row.ra));
  }
  for (std::size_t k = 0; k < set.size(); ++k) b[rows.normal_row[k]] -= want_[static_cast<std::size_t>(set[k] - first)];
}

void ContactImpulses::solveIsland(const World& world, std::span<const Contact* const> island, IslandScratch& scratch,
                                  const StepSettings& settings, double gravity_dt, ContactSolveStats& own) {
  const ContactRows& rows = scratch.rows;
  auto b = scratch.b.view(rows.size()), f = scratch.p.view(rows.size());
  // An island that may be pivoted must converge to near rounding (tuning::kSmallIslandTolerance).
  const bool small = !tooLargeToPivot(island.size(), settings.contact.max_direct_rows);
  IslandImpulseSettings gs;
  gs.max_sweeps = small ? std::min(settings.time_stepping_sweeps, tuning::kSmallIslandSweeps)
                        : settings.time_stepping_sweeps;
  // A speed setting pivots only the small islands its sweeps leave unconverged at the usual
  // tolerance (a mass ratio the sweeps cannot settle), not every flat landing.
  gs.tolerance = small && !isSpeedSetting(settings) ? tuning::kSmallIslandTolerance : tuning::kImpulseTolerance;
  gs.subspace_rounds = settings.time_stepping_sweeps >= tuning::kActiveSetMinSweeps;
  gs.gravity_dt = gravity_dt;
  const bool converged = solveIslandImpulsesInPlace(world, rows, island, b, f, gs, own);
  if (!converged && small && (!isSpeedSetting(settings) || massRatio(world, island) >= kSweepsMassRatio)) {
    ContactLcp& exact = scratch.exact;
    buildContactLcp(world, island, exact);   // the same rows
    exact.problem.b = b;
    solveContactLcp(exact.problem, own, scratch.pivoted);
    if (usableLcpAnswer(scratch.pivoted, exact.problem)) f = scratch.pivoted.f;
    else {
      ++own.iterative_fallbacks;
      // No usable pivoting answer (friction passes that do not settle, on an island too large for
      // Lemke's method): the sweeps go on from theirs with a large island's cap and tolerance. The
      // small island's 30 sweeps to 1e-12 were only a first try: kept as they were, a table thrown
      // on its side into a bin's corner (an island of 40 contacts) drove a corner 2.3 mm into the
      // wall, and the projection, squeezing it between the wall and its neighbour, moved it 11 cm.
      gs.max_sweeps = settings.time_stepping_sweeps;
      gs.tolerance = tuning::kImpulseTolerance;
      if (gs.max_sweeps > tuning::kSmallIslandSweeps) solveIslandImpulsesInPlace(world, rows, island, b, f, gs, own);
    }
  }
}

bool ContactImpulses::applyImpacts(World& world, const std::vector<Contact>& contacts, const StepSettings& settings,
                                   ContactSolveStats& stats) {
  if (!impacts_ || !world.joints.empty() || isSpeedSetting(settings)) return false;
  targets(contacts, settings.dt, true);
  cacheVelocities(world);
  islands_.split(world, all_);
  islands_split_ = true;
  island_stats_.assign(islands_.size(), ContactSolveStats{});
  const Contact* const first = contacts.data();
  parallelFor(settings.threads, islands_.size(), [&](std::size_t k) {
    const std::span<const Contact* const> island = islands_[k];
    if (std::none_of(island.begin(), island.end(), [&](const Contact* c) { return bounce_[c - first] >= 0; })) return;
    thread_local IslandScratch scratch;
    buildContactRows(world, island, scratch.rows);
    velocityTerms(island, scratch.rows, first, scratch.b.view(scratch.rows.size()));
    scratch.p.view(scratch.rows.size()).setZero();   // an impact owes nothing to the last step's load
    solveIsland(world, island, scratch, settings, 0, island_stats_[k]);
    applyAlongRows(world, scratch.rows.rows, scratch.p.view(scratch.rows.size()));
    for (std::size_t c = 0; c < island.size(); ++c)
      impact_impulse_[static_cast<std::size_t>(island[c] - first)] = impulseOfContact(scratch.rows, scratch.p.view(scratch.rows.size()), c, 1.0);
  });
  for (const ContactSolveStats& own : island_stats_) stats += own;
  return true;
}

void ContactImpulses::apply(World& world, const std::vector<Contact>& contacts, const std::vector<double>& approach,
                            const StepSettings& settings, bool bounces, ContactSolveStats& stats) {
  const double dt = settings.dt;
  const std::size_t m = contacts.size();
  const std::vector<const ImpulseRecord*>& last = last_;
  const std::vector<double>& want = want_;   // normal velocity target
  const std::vector<double>& owed = owed_;   // landing speed carried in
  const std::vector<const Contact*>& all = all_;
  targets(contacts, dt, bounces);
  stats.resting += static_cast<long>(m);

  std::vector<Eigen::Vector3d>& impulse = impulse_;   // on B, world axes
  std::vector<double>& normal_impulse = normal_impulse_;
  impulse.assign(m, Eigen::Vector3d::Zero());
  normal_impulse.assign(m, 0);
  cacheVelocities(world);
  auto indexOf = [&](const Contact* c) { return static_cast<std::size_t>(c - contacts.data()); };
  // The impulses of one set of contacts (an island, or all of them) along their rows: applied, and
  // kept per contact for the records.
  auto store = [&](std::span<const Contact* const> set, const ContactRows& rows, Eigen::Ref<const Eigen::VectorXd> f) {
    applyAlongRows(world, rows.rows, f);
    for (std::size_t k = 0; k < set.size(); ++k) {
      const std::size_t i = indexOf(set[k]);
      impulse[i] += impulseOfContact(rows, f, k, 1.0);
      normal_impulse[i] = f[rows.normal_row[k]];
    }
  };
  if (!world.joints.empty()) {
    // Joints tie the islands together and push on the contacts: every contact and every joint row
    // in one problem (joints/contact_joint_lcp.h).
    ContactLcp exact = buildContactLcp(world, all, std::vector<char>(m, 1));
    velocityTerms(all, exact, contacts.data(), exact.problem.b);
    std::vector<JointRow> joint_rows;
    Eigen::VectorXd joint_b;
    jointStepRows(world, dt, joint_rows, joint_b);
    ContactJointSettings joined;
    joined.max_direct_rows = settings.contact.max_direct_rows;
    joined.max_sweeps = settings.time_stepping_sweeps;
    joined.contact_start = warmStart(exact, last);
    // A bounce's target on a contact the joints nearly hold already (two links folded onto each
    // other, a third touching both: A's smallest eigenvalue 5.5e-5 of its largest's 76) is met
    // exactly by impulses of hundreds of N s along that near-null direction, and those add
    // (target x impulse) of kinetic energy: 0.43 J to 11 J in one step of the chain, its links
    // turned at 146 rad/s. Nothing in the exact answer bounds it (the merit only bounds what the
    // impulses do beside their targets: passive_impulses.h). Where the answer with bounces adds
    // kinetic energy, the step is solved again with every bounce dropped (each contact only
    // stopped), which can only take energy.
    const bool bounces = std::any_of(want.begin(), want.end(), [](double w) { return w > 0; });
    if (bounces) before_.save(world);
    const double energy_before = bounces ? kineticEnergyOf(world) : 0;
    Eigen::VectorXd f = solveContactsWithJoints(world, exact, joint_rows, joint_b, joined, stats);
    if (bounces) {
      joined_.save(world);   // the joints' impulses applied
      applyAlongRows(world, exact.rows, f);
      const bool gained = kineticEnergyOf(world) > energy_before * (1 + kBounceEnergySlack);
      (gained ? before_ : joined_).restore(world);
      if (gained) {
        for (std::size_t k = 0; k < m; ++k) exact.problem.b[exact.normal_row[k]] += std::max(want[k], 0.0);
        f = solveContactsWithJoints(world, exact, joint_rows, joint_b, joined, stats);
        ++stats.passive_scaled;
      }
    }
    store(all, exact, f);
  } else {
    // Islands are solved one by one even by Gauss-Seidel: each then sweeps until it has itself
    // converged (one solve over all of them would stop quiet islands at the busiest one's tolerance).
    // They share no moving body, so they may be solved on several threads: each reads the velocities
    // of before the solve and writes its own bodies' momenta and its own contacts' impulses.
    if (!islands_split_) islands_.split(world, all);   // the impact phase's split holds: the same contacts
    island_stats_.assign(islands_.size(), ContactSolveStats{});
    parallelFor(settings.threads, islands_.size(), [&](std::size_t k) {
      const std::span<const Contact* const> island = islands_[k];
      ContactSolveStats& own = island_stats_[k];
      thread_local IslandScratch scratch;
      // Gauss-Seidel first, warm-started: most islands (a pair of boxes meeting, a stack resting
      // as it did last step) converge within a few sweeps. One that does not (a heavy box on a light
      // one: Gauss-Seidel converges at a rate set by the mass ratio; a tall stack) is solved exactly
      // by pivoting if it is small enough, and keeps the Gauss-Seidel answer otherwise (a pile).
      buildContactRows(world, island, scratch.rows);
      velocityTerms(island, scratch.rows, contacts.data(), scratch.b.view(scratch.rows.size()));
      scratch.last.resize(island.size());
      for (std::size_t c = 0; c < island.size(); ++c) scratch.last[c] = last[indexOf(island[c])];
      warmStart(scratch.rows, scratch.last, scratch.p.view(scratch.rows.size()));
      solveIsland(world, island, scratch, settings, dt, own);
      store(island, scratch.rows, scratch.p.view(scratch.rows.size()));
    });
    for (const ContactSolveStats& own : island_stats_) stats += own;
  }

  std::vector<ImpulseRecord>& records = records_;
  records.resize(m);
  parallelFor(settings.threads, m, [&](std::size_t i) {
    const Contact& c = contacts[i];
    records[i] = impulseRecord(world, c, impulse[i]);
    records[i].impact = impact_impulse_[i];
    // A landing the margin closed this step (pushed, not yet touching) is owed its bounce; one
    // still short of touching a step later carries what it was owed, once.
    const bool landing = -c.depth > settings.contact.tolerance_m && normal_impulse[i] > 0;
    const bool carried = landing && owed[i] > 0 && owed[i] > approach[i];   // owed > 0: a record exists
    records[i].landing_speed = landing ? std::max(approach[i], owed[i]) : 0;
    records[i].landing_carried = carried ? last[i]->landing_carried + 1 : 0;
  });
}

}  // namespace tumble
