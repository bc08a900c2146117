#include "dynamics/frame_record.h"

#include <algorithm>

#include "dynamics/contact_jacobian.h"
#include "dynamics/impulse_memory.h"

namespace tumble {

void worldEnergy(const World& world, double& kinetic, double& potential) {
  kinetic = 0;
  potential = 0;
  for (const RigidBody& b : world.bodies) {
    if (b.fixedByScene()) continue;
    if (!b.asleep) kinetic += b.kineticEnergy();   // a sleeper's momenta are zero
    potential -= b.mass * world.gravity.dot(b.x);
  }
}

namespace {

BroadPhaseRecord broadPhaseOf(const ContactDetector& detector) {
  BroadPhaseRecord out;
  const SweepAndPrune& broad = detector.broadPhase();
  if (detector.work().broad_phase_runs == 0) return out;   // never swept: its boxes were never set
  out.boxes.reserve(static_cast<std::size_t>(broad.size()));
  for (const BroadPhaseProxy& p : broad.proxies())
    out.boxes.push_back({p.body, p.box.min.cast<float>(), p.box.max.cast<float>()});
  out.pairs.reserve(detector.broadPhasePairs().size());
  for (const ProxyPair& p : detector.broadPhasePairs()) out.pairs.emplace_back(p.a, p.b);
  return out;
}

}  // namespace

FrameRecorder::FrameRecorder(const World& world, const StepSettings& settings, FrameRecordOptions options)
    : awake_(world), detector_(awake_), contact_(settings.contact), options_(options) {}

FrameRecord FrameRecorder::record(const World& world, const Pipeline& pipeline, std::vector<ImpactMark>& impacts,
                                  BackStepLog* back_steps) {
  FrameRecord out;
  out.time = world.time;
  out.impacts.swap(impacts);
  impacts.clear();
  if (back_steps) out.back_steps = back_steps->take();
  if (options_.broad_phase) out.broad_phase = broadPhaseOf(pipeline.detector());
  worldEnergy(world, out.kinetic, out.potential);
  out.potential += pipeline.storedEnergy();
  if (!detector_.hasCollidablePairs()) return out;
  awake_.time = world.time;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& from = world.bodies[i];
    RigidBody& to = awake_.bodies[i];
    to.x = from.x, to.q = from.q, to.P = from.P, to.L = from.L;
    to.is_static = from.fixedByScene();
    to.asleep = false;
  }
  detector_.detect(awake_, contact_, found_);
  const StepImpulses impulses = pipeline.lastImpulses();
  for (const Contact& c : found_) {
    RecordedContact r;
    r.a = c.a;
    r.b = c.b;
    r.point = c.point;
    r.normal = c.normal;
    r.depth = c.depth;
    if (impulses.memory && impulses.span_s > 0)
      if (const ImpulseRecord* rec = impulses.memory->find(world, c, ImpulseMemory::kMatchRadius)) {
        const Eigen::Vector3d impulse = rec->impulse + rec->impact;
        r.has_force = impulse.squaredNorm() > 0;
        r.force = impulse / impulses.span_s;
      }
    // In force: touching within the tolerance, or pushing (a time-stepping contact at a gap).
    if (c.depth < -contact_.tolerance_m && !r.has_force) continue;
    const RigidBody& A = world.bodies[static_cast<std::size_t>(c.a)];
    const RigidBody& B = world.bodies[static_cast<std::size_t>(c.b)];
    const Eigen::Vector3d v = pointVelocity(B, c.point) - pointVelocity(A, c.point);
    const double vn = v.dot(c.normal);
    r.state = vn < -contact_.resting_speed_m_s  ? ContactState::Colliding
              : vn > contact_.resting_speed_m_s ? ContactState::Separating
                                                : ContactState::Resting;
    if (c.friction > 0 && r.state != ContactState::Separating)
      r.friction = (v - vn * c.normal).norm() > contact_.sliding_speed_m_s ? FrictionState::Sliding
                                                                          : FrictionState::Sticking;
    out.deepest_m = std::max(out.deepest_m, c.depth);
    out.contacts.push_back(r);
  }
  return out;
}

}  // namespace tumble
