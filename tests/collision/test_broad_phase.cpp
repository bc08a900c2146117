#include <catch2/catch.hpp>

#include <random>

#include "collision/broad_phase.h"

using namespace tumble;
using Eigen::Vector3d;

namespace {

Aabb randomBox(std::mt19937& rng, double world) {
  std::uniform_real_distribution<double> pos(0, world), size(0.05, 1.0);
  const Vector3d lo(pos(rng), pos(rng), pos(rng));
  return {lo, lo + Vector3d(size(rng), size(rng), size(rng))};
}

}  // namespace

// Sweep and prune against the O(n^2) oracle on random scenes moved over many updates: small
// coherent moves (the insertion-sort case), occasional teleports (the worst case for it).
TEST_CASE("SweepAndPrune equals bruteForcePairs over many updates", "[broad_phase]") {
  const int seed = GENERATE(1, 2, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> step(-0.2, 0.2), coin(0, 1);
  SweepAndPrune sap;
  for (int i = 0, body = 0; i < 300; ++i) {
    if (coin(rng) < 0.7) ++body;  // some bodies own several pieces
    sap.add({randomBox(rng, 8.0), body, coin(rng) < 0.15});
  }
  std::vector<ProxyPair> pairs;
  std::int64_t total_pairs = 0;
  for (int update = 0; update < 100; ++update) {
    for (int i = 0; i < sap.size(); ++i) {
      if (sap.proxy(i).is_static) continue;
      Aabb b = sap.proxy(i).box;
      const Vector3d d(step(rng), step(rng), step(rng));
      b = coin(rng) < 0.01 ? randomBox(rng, 8.0) : Aabb{b.min + d, b.max + d};
      sap.setBox(i, b);
    }
    sap.findPairs(pairs);
    REQUIRE(pairs == bruteForcePairs(sap.proxies()));
    total_pairs += std::int64_t(pairs.size());
  }
  CHECK(total_pairs > 1000);  // the scenes really have contacts
}

TEST_CASE("SweepAndPrune: no static-static pairs, no pairs within one body", "[broad_phase]") {
  const Aabb box{Vector3d(0, 0, 0), Vector3d(1, 1, 1)};
  SweepAndPrune sap;
  sap.add({box, 0, true});
  sap.add({box, 1, true});
  sap.add({box, 2, false});
  sap.add({box, 2, false});
  std::vector<ProxyPair> pairs;
  sap.findPairs(pairs);
  const std::vector<ProxyPair> expected{{0, 2}, {0, 3}, {1, 2}, {1, 3}};
  CHECK(pairs == expected);
}
