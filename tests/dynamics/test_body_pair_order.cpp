// Indices ordered by their pair of bodies (base/pair_order.h): the order a comparison sort on
// (a, b, index) gives, for random pairs with many repeats and bodies of every index.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "base/pair_order.h"

using namespace tumble;

TEST_CASE("body pair order: sorted by (a, b), stable within a pair", "[body_pair_order]") {
  std::mt19937 rng(5);
  PairOrderScratch scratch;
  std::vector<std::size_t> order;
  for (int trial = 0; trial < 200; ++trial) {
    const int bodies = 1 + trial % 37;
    std::uniform_int_distribution<int> body(0, bodies - 1);
    std::vector<std::pair<int, int>> pairs(static_cast<std::size_t>(trial * 7 % 300));
    for (auto& [a, b] : pairs) a = body(rng), b = body(rng);
    std::vector<std::size_t> expected(pairs.size());
    std::iota(expected.begin(), expected.end(), std::size_t{0});
    std::sort(expected.begin(), expected.end(),
              [&](std::size_t x, std::size_t y) { return std::make_pair(pairs[x], x) < std::make_pair(pairs[y], y); });
    orderByPair(pairs.size(), [&](std::size_t i) { return pairs[i].first; },
                    [&](std::size_t i) { return pairs[i].second; }, order, scratch);
    REQUIRE(order == expected);
  }
}
