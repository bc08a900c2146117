#include "dynamics/contact_detection.h"

#include <algorithm>

#include "collision/aabb.h"
#include "dynamics/parallel_for.h"

namespace tumble {

namespace {
constexpr std::size_t kPrefetchAhead = 4;   // jobs
}  // namespace

Eigen::Isometry3d poseOf(const RigidBody& body) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = body.rotation();
  pose.translation() = body.x;
  return pose;
}

ContactDetector::ContactDetector(const World& world) {
  int moving = 0, fixed = 0;
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    const RigidBody& body = world.bodies[b];
    if (body.shape == ShapeKind::Plane) {
      planes_.push_back(static_cast<int>(b));
      continue;
    }
    (body.is_static ? fixed : moving) += 1;
    for (const ConvexPiece& piece : body.pieces) {
      pieces_.push_back({static_cast<int>(b), &piece, makeCollisionHull(piece), piece.thickness()});
      thinnest_ = std::min(thinnest_, pieces_.back().thickness);
      broad_.add({Aabb{}, static_cast<int>(b), body.is_static});
      near_broad_.add({Aabb{}, static_cast<int>(b), body.is_static});
    }
  }
  // Something can touch only if a moving body meets another body or the ground; the broad phase
  // has work only if a moving body can meet another body (the ground is tested directly).
  has_pairs_ = moving > 0 && (moving + fixed > 1 || !planes_.empty());
  has_body_pairs_ = moving > 0 && moving + fixed > 1;
  for (const Joint& j : world.joints)
    if (j.a >= 0 && j.b >= 0) joined_.emplace_back(std::min(j.a, j.b), std::max(j.a, j.b));
  std::sort(joined_.begin(), joined_.end());
}

bool ContactDetector::joined(int a, int b) const {
  if (joined_.empty()) return false;
  return std::binary_search(joined_.begin(), joined_.end(), std::pair(std::min(a, b), std::max(a, b)));
}

void ContactDetector::updateBoxes(double margin, const std::vector<double>* reach) {
  // Two boxes grown by m_a and m_b overlap when the pieces are closer than m_a + m_b: each grows by
  // half the base margin and its body's whole reach.
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const int body = pieces_[i].body;
    const double grow = reach ? 0.5 * margin + (*reach)[body] : margin;
    broad_.setBox(static_cast<int>(i), aabbOf(*pieces_[i].shape, poses_[body], grow));
  }
}

void ContactDetector::addPairContacts(const World& world, const PiecePair& pair,
                                      const ContactManifold& m, std::vector<Contact>& out,
                                      std::vector<PiecePair>* pairs) const {
  int a = pieces_[pair.piece_a].body;
  int b = pair.piece_b >= 0 ? pieces_[pair.piece_b].body : ~pair.piece_b;
  const RigidBody& A = world.bodies[a];
  const RigidBody& B = world.bodies[b];
  if (m.points.empty()) return;
  // What the manifold's points share (its pair's material, its normal's rolling radii), once.
  Contact c;
  c.a = a;
  c.b = b;
  c.normal = m.normal;
  c.restitution = combineRestitution(A.restitution, B.restitution);
  c.friction = combineFriction(A.friction, B.friction);
  c.closest_points = m.closest_points;
  c.radius_a = pieces_[pair.piece_a].shape->rollingRadius(A.q.conjugate() * m.normal);
  c.radius_b = pair.piece_b >= 0 ? pieces_[pair.piece_b].shape->rollingRadius(B.q.conjugate() * m.normal) : 0.0;
  for (const ContactPoint& p : m.points) {
    c.point = p.position;
    c.depth = p.depth;
    if (c.friction > 0) ++work_.frictional_contacts;
    out.push_back(c);
    if (pairs) pairs->push_back(pair);
  }
}

void ContactDetector::detect(const World& world, const ContactSettings& settings,
                             std::vector<Contact>& out, std::vector<PiecePair>* pairs,
                             const std::vector<double>* reach, bool reuse, int threads) {
  out.clear();
  if (pairs) pairs->clear();
  if (!has_pairs_) return;
  // Each body's pose once: every piece's box and every pair it is in read it (a rotation matrix
  // from the quaternion each time was 2 % of the 1000-box pile's step).
  poses_.resize(world.bodies.size());
  for (std::size_t b = 0; b < world.bodies.size(); ++b) poses_[b] = poseOf(world.bodies[b]);
  candidates_.clear();
  if (has_body_pairs_) {
    updateBoxes(settings.margin_m, reach);
    broad_.findPairs(candidates_);
    ++work_.broad_phase_runs;
  }
  auto reachOf = [&](int body) { return reach ? (*reach)[body] : 0.0; };
  const double slack = reuse ? kReuseSlack * settings.margin_m : 0.0;
  // The jobs, in the order their contacts are reported: pairs of pieces in the broad phase's order,
  // then each ground plane against every piece. Each job's memory (cached axis, kept manifold) is
  // its own, found here on this thread (the map may grow), so the jobs may run on any thread.
  std::size_t count = 0;
  auto nextJob = [&]() -> PairJob& {
    if (count == jobs_.size()) jobs_.emplace_back();
    return jobs_[count++];
  };
  memories_.beginStep();
  for (const ProxyPair& c : candidates_) {
    const Piece& pa = pieces_[c.a];
    const Piece& pb = pieces_[c.b];
    if (joined(pa.body, pb.body)) continue;
    PairJob& job = nextJob();
    job.key = {c.a, c.b};
    job.margin = settings.margin_m + reachOf(pa.body) + reachOf(pb.body);
    // Bodies that may travel more than the base margin in the step (falling, struck) drift out of
    // any kept manifold within a step or two: keeping theirs costs more than it saves (the falling
    // 10 000-box pile took 15 % longer when it did).
    const bool slow = job.margin <= 2 * settings.margin_m;
    job.keep = slack > 0 && slow && keeps(pa) && keeps(pb);
    job.memory_index = memories_.next(job.key);   // candidates come sorted
    job.ground_kept = nullptr;
  }
  memories_.endStep();
  const std::size_t pair_jobs = count;
  for (std::size_t k = 0; k < pair_jobs; ++k) jobs_[k].memory = &memories_[jobs_[k].memory_index];
  if (slack > 0) ground_kept_.resize(planes_.size() * pieces_.size());
  for (std::size_t g = 0; g < planes_.size(); ++g) {
    const int plane = planes_[g];
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const RigidBody& body = world.bodies[pieces_[i].body];
      if (body.is_static || joined(pieces_[i].body, plane)) continue;
      PairJob& job = nextJob();
      job.key = {static_cast<int>(i), ~plane};
      job.margin = settings.margin_m + reachOf(pieces_[i].body);
      const bool slow = job.margin <= 2 * settings.margin_m;   // as for two pieces, above
      job.keep = slack > 0 && slow && keeps(pieces_[i]);
      job.memory_index = -1;
      job.memory = nullptr;
      job.ground_kept = slack > 0 ? &ground_kept_[g * pieces_.size() + i] : nullptr;
    }
  }
  parallelFor(threads, count, [&](std::size_t k) {
    // A pair's memory lies wherever the pool had room when the pair was first met: fetching it a
    // few jobs ahead hides the cache miss the narrow phase otherwise waits on at its first read
    // (a third of collide's own time in the 1000-box pile). Only a hint: nothing read changes.
    if (k + kPrefetchAhead < pair_jobs) {
      const char* ahead = reinterpret_cast<const char*>(jobs_[k + kPrefetchAhead].memory);
      for (std::size_t line = 0; line < sizeof(PairMemory); line += 64) __builtin_prefetch(ahead + line);
    }
    runJob(world, jobs_[k], slack);
  });
  for (std::size_t k = 0; k < count; ++k) {
    const PairJob& job = jobs_[k];
    if (job.keep) ++(job.reused ? work_.manifolds_reused : work_.manifolds_built);
    if (job.found) addPairContacts(world, job.key, job.manifold, out, pairs);
  }
}

void ContactDetector::runJob(const World& world, PairJob& job, double slack) const {
  job.reused = false;
  if (job.key.piece_b < 0) {   // a piece and a ground plane
    const Piece& p = pieces_[job.key.piece_a];
    const double height = world.bodies[~job.key.piece_b].x.z();
    job.found = job.keep ? keptGroundManifold(*job.ground_kept, p, height, job.margin, slack, job.manifold, job.reused)
                         : collideGround(*p.shape, poses_[p.body], height, job.margin, job.manifold);
    return;
  }
  const Piece& pa = pieces_[job.key.piece_a];
  const Piece& pb = pieces_[job.key.piece_b];
  job.found = job.keep ? keptPairManifold(*job.memory, pa, pb, job.margin, slack, job.manifold, job.reused)
                       : collide(pa.hull, poses_[pa.body], pb.hull, poses_[pb.body], job.margin, job.memory->sat,
                                 job.manifold);
}

bool ContactDetector::keeps(const Piece& piece) {
  // A smooth piece touches at a point that rolls over its surface: no material point to keep.
  return !piece.shape->smooth();
}

bool ContactDetector::keptPairManifold(PairMemory& memory, const Piece& pa, const Piece& pb, double margin,
                                       double slack, ContactManifold& out, bool& reused) const {
  const Eigen::Isometry3d& pose_a = poses_[pa.body];
  const Eigen::Isometry3d& pose_b = poses_[pb.body];
  const Eigen::Isometry3d rel = pose_a.inverse(Eigen::Isometry) * pose_b;
  KeptManifold& kept = memory.kept;
  if (kept.valid && keptDrift(kept, rel, pb.hull.radius) + margin <= kept.margin_m + slack) {
    reused = true;
    return reuseManifold(kept, pose_a, pose_b, ReferenceIs::A, margin, out);
  }
  const bool found = collide(pa.hull, pose_a, pb.hull, pose_b, margin, memory.sat, out);
  keepManifold(out, found, pose_a, pose_b, rel, ReferenceIs::A, pa.shape, *pb.shape, margin, kept);
  return found;
}

bool ContactDetector::keptGroundManifold(KeptManifold& kept, const Piece& p, double height, double margin,
                                         double slack, ContactManifold& out, bool& reused) const {
  const Eigen::Isometry3d& pose = poses_[p.body];
  // The ground's frame is the world: the piece's pose is its pose relative to the ground.
  const Eigen::Isometry3d world = Eigen::Isometry3d::Identity();
  if (kept.valid && keptDrift(kept, pose, p.hull.radius) + margin <= kept.margin_m + slack) {
    reused = true;
    return reuseManifold(kept, world, pose, ReferenceIs::B, margin, out);
  }
  const bool found = collideGround(*p.shape, pose, height, margin, out);
  keepManifold(out, found, world, pose, pose, ReferenceIs::B, nullptr, *p.shape, margin, kept);
  return found;
}

void ContactDetector::setFixed(int body, bool fixed) {
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    if (pieces_[i].body != body) continue;
    broad_.setStatic(static_cast<int>(i), fixed);
    near_broad_.setStatic(static_cast<int>(i), fixed);
  }
}

void ContactDetector::nearPairs(const World& world, const std::vector<double>& reach,
                                std::vector<NearPair>& out) {
  out.clear();
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const int body = pieces_[i].body;
    near_broad_.setBox(static_cast<int>(i), aabbOf(*pieces_[i].shape, poseOf(world.bodies[body]), reach[body]));
  }
  near_broad_.findPairs(near_candidates_);
  for (const ProxyPair& c : near_candidates_) {
    const Piece& pa = pieces_[c.a];
    const Piece& pb = pieces_[c.b];
    if (joined(pa.body, pb.body)) continue;
    Eigen::Vector3d axis;
    double gap = separation(pa.hull, poseOf(world.bodies[pa.body]), pb.hull, poseOf(world.bodies[pb.body]),
                            near_caches_[PiecePair{c.a, c.b}], axis);
    out.push_back({pa.body, pb.body, std::max(gap, 0.0), std::min(pa.thickness, pb.thickness), axis});
  }
}

void ContactDetector::pairContacts(const World& world, const PiecePair& pair, double margin_m,
                                   std::vector<Contact>& out) {
  const Piece& pa = pieces_[pair.piece_a];
  const Eigen::Isometry3d pose_a = poseOf(world.bodies[pa.body]);
  bool found;
  if (pair.piece_b < 0) {
    found = collideGround(*pa.shape, pose_a, world.bodies[~pair.piece_b].x.z(), margin_m, manifold_);
  } else {
    const Piece& pb = pieces_[pair.piece_b];
    found = collide(pa.hull, pose_a, pb.hull, poseOf(world.bodies[pb.body]), margin_m, memories_.find(pair).sat, manifold_);
  }
  if (found) addPairContacts(world, pair, manifold_, out, nullptr);
}

ContactDetector::Overlap ContactDetector::deepestOverlap(const World& world) {
  ContactSettings overlapping;
  overlapping.margin_m = 0;
  detect(world, overlapping, overlaps_);
  Overlap deepest;
  for (const Contact& c : overlaps_)
    if (c.depth > deepest.depth) deepest = {c.depth, c.a, c.b};
  return deepest;
}

double ContactDetector::maxDepth(const World& world, const std::vector<PiecePair>& pairs) {
  double deepest = -std::numeric_limits<double>::infinity();
  for (const PiecePair& pair : pairs) {
    const Piece& pa = pieces_[pair.piece_a];
    Eigen::Isometry3d pose_a = poseOf(world.bodies[pa.body]);
    double depth;
    if (pair.piece_b < 0) {
      depth = -groundSeparation(*pa.shape, pose_a, world.bodies[~pair.piece_b].x.z());
    } else {
      const Piece& pb = pieces_[pair.piece_b];
      depth = -separation(pa.hull, pose_a, pb.hull, poseOf(world.bodies[pb.body]), memories_.find(pair).sat);
    }
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

}  // namespace tumble
