// Contact pipeline steps 1-2 (DESIGN.md): the broad phase over the AABBs of every convex piece,
// then the narrow phase on the candidate pairs, giving the world's contact points. The ground
// (plane bodies) is a half-space tested against every moving piece directly.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "collision/broad_phase.h"
#include "collision/collision_hull.h"
#include "collision/narrow_phase.h"
#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// Identifies a pair of pieces (or a piece and a ground plane) across steps.
struct PiecePair {
  int piece_a = -1, piece_b = -1;   // piece ids; a ground plane is ~body index (negative)
  friend auto operator<=>(const PiecePair&, const PiecePair&) = default;
};

class ContactDetector {
 public:
  // Keeps pointers to the world's pieces: the world must not be reallocated afterwards.
  explicit ContactDetector(const World& world);

  // All contacts of the world in its current state (pairs closer than settings.margin_m), in a
  // deterministic order; `pairs` (optional) receives the piece pair of each contact. `reach`
  // (optional, m per body) widens the margin of each pair by how far its two bodies can travel:
  // the time-stepping model's speculative contacts, without widening every pair by the fastest.
  void detect(const World& world, const ContactSettings& settings, std::vector<Contact>& out,
              std::vector<PiecePair>* pairs = nullptr, const std::vector<double>* reach = nullptr);
  // The largest penetration depth among the given piece pairs in the world's current state
  // (negative when all are separated): what bisection evaluates.
  double maxDepth(const World& world, const std::vector<PiecePair>& pairs);

  bool hasCollidablePairs() const { return has_pairs_; }

 private:
  struct Piece {
    int body;
    const ConvexPiece* shape;
    CollisionHull hull;
  };
  void updateBoxes(const World& world, double margin, const std::vector<double>* reach);
  void addPairContacts(const World& world, const PiecePair& pair, const ContactManifold& m,
                       std::vector<Contact>& out, std::vector<PiecePair>* pairs) const;

  std::vector<Piece> pieces_;
  std::vector<int> planes_;                      // body indices of ground planes
  SweepAndPrune broad_;
  std::vector<ProxyPair> candidates_;
  std::map<PiecePair, SatCache> caches_;         // ordered: deterministic iteration
  ContactManifold manifold_;
  bool has_pairs_ = false;
};

Eigen::Isometry3d poseOf(const RigidBody& body);

}  // namespace tumble
