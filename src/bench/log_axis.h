// A logarithmic axis for the benchmark plots: the whole decades that hold the data, a major tick
// on every power of ten, minor ticks at 2..9 times each, and which decades carry a label. Pure
// arithmetic, apart from the drawing, so that where the ticks fall can be tested on its own.
#pragma once

#include <string>
#include <vector>

namespace tumble::bench {

struct LogAxis {
  int lo_decade = 0, hi_decade = 1;   // the axis runs from 10^lo_decade to 10^hi_decade
  std::vector<int> majors;            // exponents e of the major ticks 10^e, ascending
  std::vector<double> minors;         // k 10^e for k = 2..9 inside the range (none when crowded)
  int label_every = 1;                // label every n-th major tick (counted from lo_decade)
  // On an axis of a single decade two labels say too little: 2 and 5 times the decade get one.
  std::vector<std::pair<double, std::string>> minor_labels;

  // Where v sits along the axis: 0 at 10^lo_decade, 1 at 10^hi_decade (log scale).
  double fraction(double v) const;
  bool labelled(int e) const { return (e - lo_decade) % label_every == 0; }
};

// The axis over positive data in [lo, hi], widened to whole decades and to at least one. A value
// within 1e-9 decade of a power of ten counts as that power (1e-3 read back from text is not
// exactly 10^-3). More than `max_labels` decades: labels on every 2nd, 3rd ... decade; more than
// `max_minor_decades`: no minor ticks, which would merge into a grey band.
LogAxis logAxis(double lo, double hi, int max_labels = 8, int max_minor_decades = 10);

// "10⁻³", "10⁰", "10²": the label of the major tick 10^e, in Unicode superscripts.
std::string decadeLabel(int e);
// The label of the minor tick k 10^e: plain from 0.001 to 100 ("0.2", "5", "50"), else "2×10⁻⁵".
std::string minorLabel(int k, int e);

}  // namespace tumble::bench
