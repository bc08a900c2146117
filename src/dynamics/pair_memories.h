// What detection keeps per pair of pieces between steps (the narrow phase's cached axis, the kept
// manifold), held only while the broad phase reports the pair: a pair whose boxes have parted is
// forgotten, as Bullet and Box2D destroy a pair's persistent manifold when its boxes stop
// overlapping. So the memory held is that of the pairs near one another now, not of every pair
// that ever was (a long run of a moving pile meets ever more), and a step finds
// each pair's memory by walking last step's sorted list beside this step's sorted candidates,
// not by a lookup per pair (a tree's lookups were 5 % of the 1000-box pile's step).
#pragma once

#include <compare>
#include <cstddef>
#include <map>
#include <vector>

#include "collision/kept_manifold.h"
#include "collision/narrow_phase.h"

namespace tumble {

// Identifies a pair of pieces (or a piece and a ground plane) across steps.
struct PiecePair {
  int piece_a = -1, piece_b = -1;   // piece ids; a ground plane is ~body index (negative)
  friend auto operator<=>(const PiecePair&, const PiecePair&) = default;
};

struct PairMemory {
  SatCache sat;
  KeptManifold kept;
};

class PairMemories {
 public:
  // A step's pairs are given in increasing order between beginStep and endStep; each gets last
  // step's memory if it was given then, a fresh one otherwise. endStep forgets the pairs of last
  // step not given again. Indices stay valid until the next beginStep.
  void beginStep();
  int next(const PiecePair& key);
  void endStep();
  PairMemory& operator[](int index) { return pool_[index]; }

  // The memory of any pair between steps (the Baraff model's back-stepping asks for a pair it
  // holds): this step's if the pair is in its list, else one kept aside until the pair is given.
  PairMemory& find(const PiecePair& key);

  // Pairs remembered now (this step's list and those kept aside).
  std::size_t size() const { return live_.size() + aside_.size(); }

 private:
  struct Slot {
    PiecePair key;
    int index;   // into pool_
  };
  int acquire(const PiecePair& key);   // a fresh memory, or the one kept aside for key
  void release(int index);
  std::vector<PairMemory> pool_;       // indexed by Slot::index; freed entries reset and reused
  std::vector<int> free_;
  std::vector<Slot> live_, next_;      // last step's pairs (sorted), this step's as given
  std::size_t walked_ = 0;             // how far beginStep..next has read live_
  std::map<PiecePair, PairMemory> aside_;
};

}  // namespace tumble
