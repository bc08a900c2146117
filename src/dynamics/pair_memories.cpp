#include "dynamics/pair_memories.h"

#include <algorithm>
#include <cassert>

namespace tumble {

void PairMemories::beginStep() {
  next_.clear();
  walked_ = 0;
}

int PairMemories::next(const PiecePair& key) {
  assert((next_.empty() || next_.back().key < key) && "pairs are given in increasing order");
  while (walked_ < live_.size() && live_[walked_].key < key) release(live_[walked_++].index);
  const int index = walked_ < live_.size() && live_[walked_].key == key ? live_[walked_++].index : acquire(key);
  next_.push_back({key, index});
  return index;
}

void PairMemories::endStep() {
  while (walked_ < live_.size()) release(live_[walked_++].index);
  live_.swap(next_);   // next_ keeps last step's list until beginStep clears it
}

PairMemory& PairMemories::find(const PiecePair& key) {
  // Between steps live_ is this step's sorted list.
  auto at = std::lower_bound(live_.begin(), live_.end(), key, [](const Slot& s, const PiecePair& k) { return s.key < k; });
  if (at != live_.end() && at->key == key) return pool_[at->index];
  return aside_[key];
}

int PairMemories::acquire(const PiecePair& key) {
  int index;
  if (free_.empty()) {
    index = static_cast<int>(pool_.size());
    pool_.emplace_back();
  } else {
    index = free_.back();
    free_.pop_back();
  }
  if (!aside_.empty()) {
    auto it = aside_.find(key);
    if (it != aside_.end()) {
      pool_[index] = it->second;
      aside_.erase(it);
    }
  }
  return index;
}

void PairMemories::release(int index) {
  pool_[index] = PairMemory{};
  free_.push_back(index);
}

}  // namespace tumble
