// A linear axis with round ticks: steps of 1, 2 or 5 times a power of ten, the range widened to
// whole steps. Pure arithmetic, so where the ticks fall can be tested without drawing.
#pragma once

#include <string>
#include <vector>

namespace tumble::plot {

struct LinearAxis {
  double lo = 0, hi = 1;        // the axis runs from lo to hi (whole steps)
  double step = 0.2;
  std::vector<double> ticks;    // lo, lo + step, ..., hi
  // Where v sits along the axis: 0 at lo, 1 at hi.
  double fraction(double v) const { return (v - lo) / (hi - lo); }
};

// The axis over data in [lo, hi] with about `target_ticks` ticks. An empty range (lo == hi) gets
// one step either side; non-finite bounds give 0..1.
LinearAxis linearAxis(double lo, double hi, int target_ticks = 6);

// A tick's label: as many decimals as the step needs, "-0" written "0" ("0.25", "10", "-1.5").
std::string tickLabel(double v, double step);

}  // namespace tumble::plot
