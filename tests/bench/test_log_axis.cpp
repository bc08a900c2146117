// Where the log axes of the benchmark plots put their ticks: pure arithmetic, no drawing.
#include <catch2/catch.hpp>
#include <cmath>

#include "bench/log_axis.h"

using namespace tumble::bench;

TEST_CASE("a log axis spans the whole decades around the data, a major tick on each") {
  const LogAxis a = logAxis(3e-5, 8e-3);
  CHECK(a.lo_decade == -5);
  CHECK(a.hi_decade == -2);
  CHECK(a.majors == std::vector<int>{-5, -4, -3, -2});
  CHECK(a.label_every == 1);
  // A decade is a third of this axis; 10^-4 sits one third along, 3e-5 a little below half of
  // the first third (log10 3 = 0.477).
  CHECK(a.fraction(1e-5) == Approx(0).margin(1e-12));
  CHECK(a.fraction(1e-4) == Approx(1.0 / 3));
  CHECK(a.fraction(1e-2) == Approx(1));
  CHECK(a.fraction(3e-5) == Approx(std::log10(3.0) / 3));
  CHECK(logAxis(3e-5, 2e-2).hi_decade == -1);   // 2e-2 is past 10^-2
}

TEST_CASE("minor ticks at 2..9 times each decade, none outside the range") {
  const LogAxis a = logAxis(3e-5, 8e-3);
  REQUIRE(a.minors.size() == 3 * 8);
  CHECK(a.minors.front() == Approx(2e-5));
  CHECK(a.minors[7] == Approx(9e-5));
  CHECK(a.minors[8] == Approx(2e-4));
  CHECK(a.minors.back() == Approx(9e-3));
  for (double v : a.minors) {
    CHECK(v > 1e-5);
    CHECK(v < 1e-2);
  }
}

TEST_CASE("data on a power of ten, as read back from 9-digit text, adds no decade") {
  const LogAxis a = logAxis(0.00100000000000000002, 1.00000000001);
  CHECK(a.lo_decade == -3);
  CHECK(a.hi_decade == 0);
  const LogAxis b = logAxis(0.000999999999, 1.0);   // rounded down by the text: still 10^-3
  CHECK(b.lo_decade == -3);
  const LogAxis c = logAxis(0.00099, 1.0);          // truly below 10^-3
  CHECK(c.lo_decade == -4);
}

TEST_CASE("data within one decade still gets a whole decade") {
  const LogAxis a = logAxis(5e-3, 6e-3);
  CHECK(a.lo_decade == -3);
  CHECK(a.hi_decade == -2);
  const LogAxis b = logAxis(1e-3, 1e-3);
  CHECK(b.lo_decade == -3);
  CHECK(b.hi_decade == -2);
}

TEST_CASE("a crowded log axis labels every n-th decade and drops its minor ticks") {
  const LogAxis a = logAxis(1e-17, 1e3);   // 20 decades
  CHECK(a.majors.size() == 21);
  CHECK(a.label_every == 3);
  CHECK(a.labelled(-17));
  CHECK(!a.labelled(-16));
  CHECK(a.labelled(-14));
  CHECK(a.minors.empty());
  CHECK(logAxis(1e-8, 1).label_every == 1);
  CHECK(logAxis(1e-9, 1).label_every == 2);
}

TEST_CASE("decade labels are powers of ten in superscripts") {
  CHECK(decadeLabel(0) == "10⁰");
  CHECK(decadeLabel(-3) == "10⁻³");
  CHECK(decadeLabel(2) == "10²");
  CHECK(decadeLabel(-12) == "10⁻¹²");
}

TEST_CASE("an axis of one decade also labels 2 and 5 times it") {
  const LogAxis a = logAxis(0.15, 0.9);
  REQUIRE(a.minor_labels.size() == 2);
  CHECK(a.minor_labels[0].first == Approx(0.2));
  CHECK(a.minor_labels[0].second == "0.2");
  CHECK(a.minor_labels[1].second == "0.5");
  CHECK(logAxis(1e-3, 1).minor_labels.empty());
  CHECK(minorLabel(2, -5) == "2×10⁻⁵");
  CHECK(minorLabel(5, -3) == "0.005");
  CHECK(minorLabel(5, 0) == "5");
  CHECK(minorLabel(2, 1) == "20");
  CHECK(minorLabel(2, 2) == "2×10²");
}
