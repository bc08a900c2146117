// -s/-e and --frames lists.
#include <catch2/catch.hpp>

#include "app/frame_selection.h"
#include "base/error.h"

using namespace tumble;

TEST_CASE("frames default to the whole clip, counted from 1", "[cli]") {
  CHECK(selectFrames(4, {}, {}, "") == std::vector<int>{1, 2, 3, 4});
  CHECK(selectFrames(10, 3, 5, "") == std::vector<int>{3, 4, 5});
}

TEST_CASE("frame lists (--frames) take numbers and ranges, and ranges, sorted and deduplicated", "[cli]") {
  CHECK(selectFrames(30, {}, {}, "1,5,10..12, 5") == std::vector<int>{1, 5, 10, 11, 12});
}

TEST_CASE("bad frame selections are usage errors", "[cli]") {
  CHECK_THROWS_AS(selectFrames(10, {}, {}, "0"), Error);
  CHECK_THROWS_AS(selectFrames(10, {}, {}, "11"), Error);
  CHECK_THROWS_AS(selectFrames(10, {}, {}, "5..3"), Error);
  CHECK_THROWS_AS(selectFrames(10, {}, {}, "a"), Error);
  CHECK_THROWS_AS(selectFrames(10, 5, 3, ""), Error);
  CHECK_THROWS_AS(selectFrames(10, 1, {}, "2"), Error);
}
