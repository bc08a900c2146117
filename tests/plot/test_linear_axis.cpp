#include <catch2/catch.hpp>

#include "plot/linear_axis.h"

using namespace tumble::plot;

TEST_CASE("a linear axis widens its range to round steps of 1, 2 or 5 x 10^k", "[plot]") {
  const LinearAxis a = linearAxis(0.03, 3.97, 8);
  CHECK(a.step == Approx(0.5));
  CHECK(a.lo == 0);
  CHECK(a.hi == Approx(4));
  REQUIRE(a.ticks.size() == 9);
  CHECK(a.ticks[3] == Approx(1.5));
  const LinearAxis b = linearAxis(-1234, 87, 7);
  CHECK(b.step == Approx(500));
  CHECK(b.lo == Approx(-1500));
  CHECK(b.hi == Approx(500));
  CHECK(a.fraction(2) == Approx(0.5));
}

TEST_CASE("a linear axis over one value still has a range, and labels read as the step needs", "[plot]") {
  const LinearAxis a = linearAxis(12, 12);
  CHECK(a.lo < 12);
  CHECK(a.hi > 12);
  CHECK(tickLabel(0.25, 0.05) == "0.25");
  CHECK(tickLabel(10, 5) == "10");
  CHECK(tickLabel(-1e-17, 0.5) == "0.0");
  CHECK(tickLabel(-1.5, 0.5) == "-1.5");
}
