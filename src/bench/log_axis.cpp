#include "bench/log_axis.h"

#include <cmath>
#include <cstdlib>

namespace tumble::bench {

double LogAxis::fraction(double v) const {
  return (std::log10(v) - lo_decade) / (hi_decade - lo_decade);
}

LogAxis logAxis(double lo, double hi, int max_labels, int max_minor_decades) {
  constexpr double kSlack = 1e-9;   // decades: rounding in a value read back from 9-digit text
  LogAxis a;
  a.lo_decade = static_cast<int>(std::floor(std::log10(lo) + kSlack));
  a.hi_decade = static_cast<int>(std::ceil(std::log10(hi) - kSlack));
  if (a.hi_decade <= a.lo_decade) a.hi_decade = a.lo_decade + 1;
  const int decades = a.hi_decade - a.lo_decade;
  for (int e = a.lo_decade; e <= a.hi_decade; ++e) a.majors.push_back(e);
  a.label_every = (decades + max_labels - 1) / max_labels;
  if (decades <= max_minor_decades)
    for (int e = a.lo_decade; e < a.hi_decade; ++e)
      for (int k = 2; k <= 9; ++k) a.minors.push_back(k * std::pow(10.0, e));
  if (decades == 1)
    for (int k : {2, 5}) a.minor_labels.push_back({k * std::pow(10.0, a.lo_decade), minorLabel(k, a.lo_decade)});
  return a;
}

std::string decadeLabel(int e) {
  static const char* const kSuperscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = "10";
  if (e < 0) out += "⁻";
  const std::string digits = std::to_string(std::abs(e));
  for (char d : digits) out += kSuperscript[d - '0'];
  return out;
}

std::string minorLabel(int k, int e) {
  if (e < -3 || e > 1) return std::to_string(k) + "×" + decadeLabel(e);
  if (e >= 0) return std::to_string(k) + std::string(static_cast<std::size_t>(e), '0');
  return "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + std::to_string(k);
}

}  // namespace tumble::bench
