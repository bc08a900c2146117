#include "plot/linear_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::plot {

LinearAxis linearAxis(double lo, double hi, int target_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo < 1e-12 * std::max({1.0, std::abs(lo), std::abs(hi)})) {
    const double pad = lo == 0 ? 1 : std::abs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  // Of the steps 1, 2, 5 and 10 x 10^k around the range's n-th part, the one whose ticks number
  // nearest the target (the larger on a tie: fewer labels crowd less).
  const double raw = (hi - lo) / std::max(1, target_ticks - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  LinearAxis axis;
  long best_gap = -1;
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    const double step = k * decade;
    const long first = static_cast<long>(std::floor(lo / step + 1e-9));
    const long last = std::max(static_cast<long>(std::ceil(hi / step - 1e-9)), first + 1);
    const long gap = std::abs(last - first + 1 - target_ticks);
    if (best_gap >= 0 && gap > best_gap) continue;
    best_gap = gap;
    axis.step = step;
    axis.lo = static_cast<double>(first) * step;
    axis.hi = static_cast<double>(last) * step;
    axis.ticks.clear();
    for (long i = first; i <= last; ++i) axis.ticks.push_back(static_cast<double>(i) * step);
  }
  return axis;
}

std::string tickLabel(double v, double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
  if (std::abs(v) < step * 1e-6) v = 0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace tumble::plot
