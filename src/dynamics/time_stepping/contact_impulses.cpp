#include "dynamics/time_stepping/contact_impulses.h"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"
#include "dynamics/island_impulses.h"
#include "dynamics/joints/contact_joint_lcp.h"
#include "dynamics/joints/joint_impulses.h"
#include "dynamics/parallel_for.h"

namespace tumble {

void ContactImpulses::apply(World& world, const std::vector<Contact>& contacts, const std::vector<double>& approach,
                            const StepSettings& settings, double min_bounce_speed, ContactSolveStats& stats) {
  const double dt = settings.dt;
  const std::size_t m = contacts.size();
  std::vector<const ImpulseRecord*> last(m);
  std::vector<double> want(m), owed(m, 0);   // normal velocity target; landing speed carried in
  std::vector<const Contact*> all(m);
  // Per contact, on the threads: last step's impulse (a search of the memory) and the targets.
  parallelFor(settings.threads, m, [&](std::size_t i) {
    const Contact& c = contacts[i];
    all[i] = &c;
    last[i] = memory_.find(world, c, ImpulseMemory::kMatchRadius);
    owed[i] = last[i] && last[i]->landing_carried <= kOwedBounceCarries ? last[i]->landing_speed : 0;
    const double gap = -c.depth;
    want[i] = -std::max(gap, 0.0) / dt;
    const double u = std::max(approach[i], owed[i]);
    if (gap <= settings.contact.tolerance_m && u > min_bounce_speed) want[i] = std::max(want[i], c.restitution * u);
  });
  stats.resting += static_cast<long>(m);

  std::vector<Eigen::Vector3d> impulse(m, Eigen::Vector3d::Zero());   // on B, world axes
  std::vector<double> normal_impulse(m, 0);
  // Each body's velocity once (the rows need it twice each; computing omega costs a rotation).
  velocity_.resize(world.bodies.size());
  spin_.resize(world.bodies.size());
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    const RigidBody& body = world.bodies[k];
    velocity_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.velocity();
    spin_[k] = body.is_static ? Eigen::Vector3d::Zero() : body.angularVelocity();
  }
  auto rowVelocityNow = [&](const ContactRow& r) {
    return r.dir.dot(velocity_[r.b] + spin_[r.b].cross(r.rb) - velocity_[r.a] - spin_[r.a].cross(r.ra));
  };
  // The impulses of one set of contacts (an island, or all of them) along their rows: applied, and
  // kept per contact for the records.
  auto store = [&](const std::vector<const Contact*>& set, const ContactRows& rows, const Eigen::VectorXd& f) {
    applyAlongRows(world, rows.rows, f);
    const std::vector<Eigen::Vector3d> set_impulse = impulsePerContact(rows, f, 1.0);
    for (std::size_t k = 0; k < set.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(set[k] - contacts.data());
      impulse[i] += set_impulse[k];
      normal_impulse[i] = f[rows.normal_row[k]];
    }
  };
  // The b of a set's rows: each row's velocity now, less its contact's normal target.
  auto velocityTerms = [&](const std::vector<const Contact*>& set, const ContactRows& rows) {
    Eigen::VectorXd b(rows.size());
    for (int r = 0; r < rows.size(); ++r) b[r] = rowVelocityNow(rows.rows[r]);
    for (std::size_t k = 0; k < set.size(); ++k)
      b[rows.normal_row[k]] -= want[static_cast<std::size_t>(set[k] - contacts.data())];
    return b;
  };
  if (!world.joints.empty()) {
    // Joints tie the islands together and push on the contacts: every contact and every joint row
    // in one problem (joints/contact_joint_lcp.h).
    ContactLcp exact = buildContactLcp(world, all, std::vector<char>(m, 1));
    exact.problem.b = velocityTerms(all, exact);
    std::vector<JointRow> joint_rows;
    Eigen::VectorXd joint_b;
    jointStepRows(world, dt, joint_rows, joint_b);
    ContactJointSettings joined;
    joined.max_direct_rows = settings.contact.max_direct_rows;
    joined.max_sweeps = settings.time_stepping_sweeps;
    joined.contact_start = warmStart(exact, last);
    store(all, exact, solveContactsWithJoints(world, exact, joint_rows, joint_b, joined, stats));
  } else {
    // Islands are solved one by one even by Gauss-Seidel: each then sweeps until it has itself
    // converged (one solve over all of them would stop quiet islands at the busiest one's tolerance).
    // They share no moving body, so they may be solved on several threads: each reads the velocities
    // of before the solve and writes its own bodies' momenta and its own contacts' impulses.
    const std::vector<std::vector<const Contact*>> islands = splitIntoIslands(world, all);
    std::vector<ContactSolveStats> island_stats(islands.size());
    parallelFor(settings.threads, islands.size(), [&](std::size_t k) {
      const std::vector<const Contact*>& island = islands[k];
      ContactSolveStats& own = island_stats[k];
      // Gauss-Seidel first, warm-started: most islands (a pair of boxes meeting, a stack resting
      // as it did last step) converge within a few sweeps. One that does not (a heavy box on a light
      // one: Gauss-Seidel converges at a rate set by the mass ratio; a tall stack) is solved exactly
      // by pivoting if it is small enough, and keeps the Gauss-Seidel answer otherwise (a pile).
      const ContactRows rows = buildContactRows(world, island);
      std::vector<const ImpulseRecord*> island_last(island.size());
      const Eigen::VectorXd b = velocityTerms(island, rows);
      for (std::size_t c = 0; c < island.size(); ++c)
        island_last[c] = last[static_cast<std::size_t>(island[c] - contacts.data())];
      // An island that may be pivoted must converge to near rounding (tuning::kSmallIslandTolerance).
      const bool small = !tooLargeToPivot(island.size(), settings.contact.max_direct_rows);
      IslandImpulseSettings gs;
      gs.max_sweeps = small ? std::min(settings.time_stepping_sweeps, tuning::kSmallIslandSweeps)
                            : settings.time_stepping_sweeps;
      gs.tolerance = small ? tuning::kSmallIslandTolerance : tuning::kImpulseTolerance;
      gs.subspace_rounds = settings.time_stepping_sweeps >= tuning::kActiveSetMinSweeps;
      IslandImpulses solved = solveIslandImpulses(world, rows, island, b, warmStart(rows, island_last), gs, own);
      Eigen::VectorXd f = std::move(solved.p);
      if (!solved.converged && small) {
        ContactLcp exact = buildContactLcp(world, island, std::vector<char>(island.size(), 1));   // same rows
        exact.problem.b = b;
        lcp::LcpResult r = solveContactLcp(exact.problem, own);
        if (usableLcpAnswer(r, exact.problem)) f = r.f;
        else ++own.iterative_fallbacks;
      }
      store(island, rows, f);
    });
    for (const ContactSolveStats& own : island_stats) stats += own;
  }

  std::vector<ImpulseRecord> records(m);
  parallelFor(settings.threads, m, [&](std::size_t i) {
    const Contact& c = contacts[i];
    records[i] = impulseRecord(world, c, impulse[i]);
    // A landing the margin closed this step (pushed, not yet touching) is owed its bounce; one
    // still short of touching a step later carries what it was owed, once.
    const bool landing = -c.depth > settings.contact.tolerance_m && normal_impulse[i] > 0;
    const bool carried = landing && owed[i] > 0 && owed[i] > approach[i];   // owed > 0: a record exists
    records[i].landing_speed = landing ? std::max(approach[i], owed[i]) : 0;
    records[i].landing_carried = carried ? last[i]->landing_carried + 1 : 0;
  });
  memory_.replace(std::move(records));
}

}  // namespace tumble
