// Detection's per-pair memory (pair_memories.h): kept while the broad phase reports the pair step
// after step, forgotten the first step it does not, and bounded by the pairs of one step.
#include <catch2/catch.hpp>

#include <vector>

#include "dynamics/pair_memories.h"

using namespace tumble;

namespace {

// Gives one step's pairs (sorted) and marks each memory's cached face with `mark` where it had
// none: a memory kept from an earlier step shows that step's mark.
std::vector<int> step(PairMemories& memories, const std::vector<PiecePair>& pairs, int mark) {
  std::vector<int> seen;
  memories.beginStep();
  for (const PiecePair& p : pairs) {
    PairMemory& m = memories[memories.next(p)];
    if (m.sat.index_a < 0) m.sat.index_a = mark;
    seen.push_back(m.sat.index_a);
  }
  memories.endStep();
  return seen;
}

}  // namespace

TEST_CASE("a pair's memory is kept while it is reported step after step", "[pair_memories]") {
  PairMemories memories;
  CHECK(step(memories, {{0, 1}, {0, 2}, {3, 4}}, 1) == std::vector<int>{1, 1, 1});
  CHECK(step(memories, {{0, 1}, {0, 2}, {1, 2}, {3, 4}}, 2) == std::vector<int>{1, 1, 2, 1});
  CHECK(memories.size() == 4);
}

TEST_CASE("a pair not reported for a step is forgotten", "[pair_memories]") {
  PairMemories memories;
  step(memories, {{0, 1}, {0, 2}, {3, 4}}, 1);
  step(memories, {{0, 2}}, 2);   // (0,1) and (3,4) parted
  CHECK(memories.size() == 1);
  CHECK(step(memories, {{0, 1}, {0, 2}, {3, 4}}, 3) == std::vector<int>{3, 1, 3});
}

TEST_CASE("the memory held is bounded by one step's pairs, however many pairs have met", "[pair_memories]") {
  PairMemories memories;
  for (int s = 0; s < 1000; ++s) step(memories, {{s, s + 1}, {s, s + 2}}, s);
  CHECK(memories.size() == 2);
}

TEST_CASE("a pair asked for between steps keeps its memory when it is reported", "[pair_memories]") {
  PairMemories memories;
  step(memories, {{0, 1}}, 1);
  CHECK(memories.find({0, 1}).sat.index_a == 1);   // this step's list
  memories.find({5, 6}).sat.index_a = 7;           // aside: not reported yet
  CHECK(memories.size() == 2);
  CHECK(step(memories, {{0, 1}, {5, 6}}, 2) == std::vector<int>{1, 7});
  CHECK(memories.size() == 2);
}

TEST_CASE("a forgotten pair's memory comes back fresh", "[pair_memories]") {
  PairMemories memories;
  memories.beginStep();
  PairMemory& m = memories[memories.next({0, 1})];
  m.kept.valid = true;
  m.sat.axis = SatCache::Axis::FaceA;
  memories.endStep();
  step(memories, {{2, 3}}, 1);   // (0,1) forgotten; its storage taken by (2,3) and reset
  memories.beginStep();
  const PairMemory& again = memories[memories.next({0, 1})];
  memories.endStep();
  CHECK_FALSE(again.kept.valid);
  CHECK(again.sat.axis == SatCache::Axis::None);
}
