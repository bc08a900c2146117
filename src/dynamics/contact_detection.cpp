#include "dynamics/contact_detection.h"

#include <algorithm>

#include "collision/aabb.h"

namespace tumble {

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
      pieces_.push_back({static_cast<int>(b), &piece, makeCollisionHull(piece)});
      broad_.add({Aabb{}, static_cast<int>(b), body.is_static});
    }
  }
  // Something can touch only if a moving body meets another body or the ground.
  has_pairs_ = moving > 0 && (moving + fixed > 1 || !planes_.empty());
}

void ContactDetector::updateBoxes(const World& world, double margin) {
  for (std::size_t i = 0; i < pieces_.size(); ++i)
    broad_.setBox(static_cast<int>(i),
                  aabbOf(*pieces_[i].shape, poseOf(world.bodies[pieces_[i].body]), margin));
}

void ContactDetector::addPairContacts(const World& world, const PiecePair& pair,
                                      const ContactManifold& m, std::vector<Contact>& out,
                                      std::vector<PiecePair>* pairs) const {
  int a = pieces_[pair.piece_a].body;
  int b = pair.piece_b >= 0 ? pieces_[pair.piece_b].body : ~pair.piece_b;
  const RigidBody& A = world.bodies[a];
  const RigidBody& B = world.bodies[b];
  for (const ContactPoint& p : m.points) {
    Contact c;
    c.a = a;
    c.b = b;
    c.point = p.position;
    c.normal = m.normal;
    c.depth = p.depth;
    c.restitution = combineRestitution(A.restitution, B.restitution);
    c.friction = combineFriction(A.friction, B.friction);
    out.push_back(c);
    if (pairs) pairs->push_back(pair);
  }
}

void ContactDetector::detect(const World& world, const ContactSettings& settings,
                             std::vector<Contact>& out, std::vector<PiecePair>* pairs) {
  out.clear();
  if (pairs) pairs->clear();
  if (!has_pairs_) return;
  updateBoxes(world, settings.margin_m);
  broad_.findPairs(candidates_);
  for (const ProxyPair& c : candidates_) {
    PiecePair key{c.a, c.b};
    const Piece& pa = pieces_[c.a];
    const Piece& pb = pieces_[c.b];
    if (collide(pa.hull, poseOf(world.bodies[pa.body]), pb.hull, poseOf(world.bodies[pb.body]),
                settings.margin_m, caches_[key], manifold_))
      addPairContacts(world, key, manifold_, out, pairs);
  }
  for (int plane : planes_) {
    double height = world.bodies[plane].x.z();
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const RigidBody& body = world.bodies[pieces_[i].body];
      if (body.is_static) continue;
      if (collideGround(*pieces_[i].shape, poseOf(body), height, settings.margin_m, manifold_))
        addPairContacts(world, {static_cast<int>(i), ~plane}, manifold_, out, pairs);
    }
  }
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
      depth = -separation(pa.hull, pose_a, pb.hull, poseOf(world.bodies[pb.body]), caches_[pair]);
    }
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

}  // namespace tumble
