// Broad phase: which pairs of convex pieces have overlapping AABBs (docs/architecture.md,
// detection; Yang, "Rigid Bodies and Contacts", 2020: "sweep/sort algorithm O(n log n + k)").
// Sort and sweep on one axis, the order
// kept between steps and repaired with insertion sort, which is near O(n) when bodies move little.
#pragma once

#include <cstdint>
#include <vector>

#include "base/pair_order.h"
#include "collision/aabb.h"

namespace tumble {

struct BroadPhaseProxy {
  Aabb box;                // world, already grown by the contact margin (and swept, if wanted)
  int body = -1;           // owning body: two pieces of one body never pair
  bool is_static = false;  // static-static pairs never appear
};

// Proxy indices, a < b. Lists of pairs are sorted by (a, b): deterministic, independent of the
// sort order on the sweep axis.
struct ProxyPair {
  int a = -1, b = -1;
  friend bool operator==(const ProxyPair&, const ProxyPair&) = default;
  friend auto operator<=>(const ProxyPair&, const ProxyPair&) = default;
};

class SweepAndPrune {
 public:
  // Proxies are added once, when the world is built; the index returned names the proxy.
  int add(const BroadPhaseProxy& proxy);
  void setBox(int proxy, const Aabb& box) { proxies_[proxy].box = box; }
  // A sleeping body is static until it wakes (dynamics/sleeping.h): its pairs with static proxies go.
  void setStatic(int proxy, bool is_static) { proxies_[proxy].is_static = is_static; }
  const BroadPhaseProxy& proxy(int i) const { return proxies_[i]; }
  int size() const { return int(proxies_.size()); }
  const std::vector<BroadPhaseProxy>& proxies() const { return proxies_; }
  int sweepAxis() const { return axis_; }  // -1 until the first findPairs
  std::int64_t swapsLastUpdate() const { return swaps_; }  // insertion-sort work, for --stats

  // Re-sorts and writes every overlapping pair into `pairs` (cleared first; its capacity is reused).
  void findPairs(std::vector<ProxyPair>& pairs);

 private:
  // A copy of the proxy in sweep order: the inner loop reads contiguous memory only.
  struct Entry {
    double min, max;            // the interval on the sweep axis
    double lo1, hi1, lo2, hi2;  // the intervals on the other two axes
    int proxy, body;
    bool is_static;
  };

  void chooseAxis();
  void refreshAndSort();
  void sortPairs(std::vector<ProxyPair>& pairs);   // by (a, b)

  std::vector<BroadPhaseProxy> proxies_;
  std::vector<Entry> order_;  // sorted by (min, proxy)
  int axis_ = -1;
  std::int64_t swaps_ = 0;
  std::vector<ProxyPair> sorted_;            // sortPairs' buffers, kept between steps
  std::vector<std::size_t> order_of_pairs_;
  PairOrderScratch pair_order_;
};

// The O(n^2) oracle the tests hold SweepAndPrune to: same filters, same order.
std::vector<ProxyPair> bruteForcePairs(const std::vector<BroadPhaseProxy>& proxies);

// The filter both use: boxes overlap, not both static, not the same body.
bool proxiesMayCollide(const BroadPhaseProxy& p, const BroadPhaseProxy& q);

}  // namespace tumble
