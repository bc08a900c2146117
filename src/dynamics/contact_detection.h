// Detection (docs/architecture.md): the broad phase over the AABBs of every convex piece,
// then the narrow phase on the candidate pairs, giving the world's contact points. The ground
// (plane bodies) is a half-space tested against every moving piece directly.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "collision/broad_phase.h"
#include "collision/collision_hull.h"
#include "collision/kept_manifold.h"
#include "collision/narrow_phase.h"
#include "dynamics/contact.h"
#include "dynamics/pair_memories.h"
#include "dynamics/world.h"

namespace tumble {

class ContactDetector {
 public:
  // Keeps pointers to the world's pieces: the world must not be reallocated afterwards.
  explicit ContactDetector(const World& world);

  // All contacts of the world in its current state (pairs closer than settings.margin_m), in a
  // deterministic order; `pairs` (optional) receives the piece pair of each contact. `reach`
  // (optional, m per body) widens the margin of each pair by how far its two bodies can travel:
  // the time-stepping model's speculative contacts, without widening every pair by the fastest.
  // `reuse` (the time-stepping model's choice, ContactSettings::reuse_manifolds) keeps each
  // polyhedral pair's manifold and reuses it while the pair has moved less than kReuseSlack of
  // the margin (collision/kept_manifold.h); off, every pair goes through the narrow phase.
  // `threads` run the pairs' narrow phases (parallel_for.h): the contacts, their order and every
  // bit of them are the same at any count.
  void detect(const World& world, const ContactSettings& settings, std::vector<Contact>& out,
              std::vector<PiecePair>* pairs = nullptr, const std::vector<double>* reach = nullptr,
              bool reuse = false, int threads = 1);
  // A kept manifold is reused while its pair has moved (and its margin grown) by less than this
  // share of the base margin since the narrow phase built it: 0.1 mm of the 1 mm margin. What it
  // may miss is a feature that was beyond the margin then: such a feature is still farther than
  // the margin less the slack, and within a step it closes no more than the reach the margin
  // holds beyond the base margin, so it ends the step 0.9 mm apart at least: nothing it misses
  // can touch before the narrow phase runs again.
  static constexpr double kReuseSlack = 0.1;
  // The largest penetration depth among the given piece pairs in the world's current state
  // (negative when all are separated): what bisection evaluates.
  double maxDepth(const World& world, const std::vector<PiecePair>& pairs);
  // The deepest overlap of any two pieces in the world's current state, from its own detection
  // with no margin (whatever contacts a model holds): depth 0 and bodies -1 when nothing overlaps.
  struct Overlap {
    double depth = 0;
    int a = -1, b = -1;
  };
  Overlap deepestOverlap(const World& world);
  // The contact points of one pair in the world's current state (pairs closer than margin_m),
  // appended to `out`: what back-stepping watches when a touching pair lands a new corner.
  void pairContacts(const World& world, const PiecePair& pair, double margin_m, std::vector<Contact>& out);

  // A pair of pieces that may meet within the bodies' reach: the candidates of the tunnelling
  // bound (baraff/tunnelling_bound.cpp). `gap` is a lower bound on their distance now (0 when touching or
  // overlapping), found along `axis` (world, unit, from a to b; zero if none was valid);
  // `thickness` the thinner piece's width, the most the two may overlap unseen.
  struct NearPair {
    int body_a, body_b;
    double gap, thickness;
    Eigen::Vector3d axis;
  };
  // Every pair of pieces, at least one of them moving, whose boxes grown by their bodies' `reach`
  // (m) overlap. Ground planes are left out: a half-space cannot be passed through.
  void nearPairs(const World& world, const std::vector<double>& reach, std::vector<NearPair>& out);

  // A body falling asleep is static to the broad phases until it wakes (sleeping.h): no pairs with
  // static pieces or other sleepers, and no ground test.
  void setFixed(int body, bool fixed);

  // A piece's collision hull (piece ids as in PiecePair, not ground planes).
  const CollisionHull& hull(int piece) const { return pieces_[piece].hull; }

  bool hasCollidablePairs() const { return has_pairs_; }
  // The broad phase as its last sweep left it (the broad_phase overlay, frame_record.h): each
  // piece's box and the candidate pairs (empty when it has never swept: no two bodies can meet).
  const SweepAndPrune& broadPhase() const { return broad_; }
  const std::vector<ProxyPair>& broadPhasePairs() const { return candidates_; }
  // What detection had to do, counted over the run: a stage a scene does not need stays at zero
  // ("model only what a scene needs"). Friction rows are built only for frictional contacts.
  struct Work {
    long broad_phase_runs = 0;      // sweeps of the broad phase (none with one moving body alone)
    long frictional_contacts = 0;   // contacts with a friction coefficient above zero
    long manifolds_built = 0;       // pairs through the narrow phase while reusing (detect(reuse))
    long manifolds_reused = 0;      // pairs whose kept manifold was reused instead
  };
  const Work& work() const { return work_; }
  // The thinnest width of any piece (m): infinity when there are none.
  double thinnestPiece() const { return thinnest_; }

 private:
  std::vector<Contact> overlaps_;   // scratch of deepestOverlap
  struct Piece {
    int body;
    const ConvexPiece* shape;
    CollisionHull hull;
    double thickness;   // m, the smallest extent along a face normal
  };
  static bool keeps(const Piece& piece);   // whether a piece's manifolds may be kept
  void updateBoxes(double margin, const std::vector<double>* reach);   // from poses_
  void addPairContacts(const World& world, const PiecePair& pair, const ContactManifold& m,
                       std::vector<Contact>& out, std::vector<PiecePair>* pairs) const;
  // The manifold of two pieces or of a piece and the ground within `margin`, from the kept one
  // where it may be reused (`reused` set), else from the narrow phase (then kept); false when none.
  bool keptPairManifold(PairMemory& memory, const Piece& pa, const Piece& pb, double margin, double slack,
                        ContactManifold& out, bool& reused) const;
  bool keptGroundManifold(KeptManifold& kept, const Piece& piece, double height, double margin, double slack,
                          ContactManifold& out, bool& reused) const;
  // One pair of pieces, or a piece and a ground plane, of detect(): it reads the poses and writes
  // only its own memory and outputs, so jobs may run on any thread.
  struct PairJob {
    PiecePair key;
    double margin = 0;
    bool keep = false;                      // through the kept manifold
    int memory_index = -1;                  // two pieces: in memories_
    PairMemory* memory = nullptr;           // set once every pair of the step has its memory
    KeptManifold* ground_kept = nullptr;    // a piece and the ground, when keeping
    bool found = false, reused = false;     // outputs
    ContactManifold manifold;
  };
  void runJob(const World& world, PairJob& job, double slack) const;
  std::vector<PairJob> jobs_;   // reused: their manifolds keep their buffers between steps

  std::vector<Piece> pieces_;
  std::vector<Eigen::Isometry3d> poses_;         // per body, as of the current detect()
  std::vector<int> planes_;                      // body indices of ground planes
  SweepAndPrune broad_;
  std::vector<ProxyPair> candidates_;
  PairMemories memories_;                        // per pair of pieces the broad phase reports
  std::vector<KeptManifold> ground_kept_;        // per (plane, piece), when reusing
  // The tunnelling bound's own broad phase and axis caches: its boxes are grown by each body's
  // reach, and it leaves the narrow phase's cached features (its face hysteresis) untouched.
  SweepAndPrune near_broad_;
  std::vector<ProxyPair> near_candidates_;
  std::map<PiecePair, SatCache> near_caches_;
  double thinnest_ = std::numeric_limits<double>::infinity();
  ContactManifold manifold_;
  // Bodies joined to each other (World::joints) never collide: their pieces meet at the joint by
  // design. Sorted (lower index first); empty without joints.
  std::vector<std::pair<int, int>> joined_;
  bool joined(int a, int b) const;
  bool has_pairs_ = false;
  bool has_body_pairs_ = false;   // two bodies, one moving: the broad phase has work
  mutable Work work_;             // counted in const helpers too
};

Eigen::Isometry3d poseOf(const RigidBody& body);

}  // namespace tumble
