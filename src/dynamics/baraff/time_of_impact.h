// Back-stepping (docs/architecture.md): when a step ends with bodies deeper in each other than the
// tolerance, find the first time within the step at which they touch, by bisection on the step
// length (Yang, "Rigid Bodies and Contacts", 2020: "bisection back-stepping"), or by regula falsi (Illinois variant) as an option.
#pragma once

#include <functional>

namespace tumble {

struct ImpactSearch {
  double time = 0;         // s into the step: the latest time found with depth <= tolerance
  double depth = 0;        // m, depth at that time
  int evaluations = 0;
};

// `depth_at(t)` gives the deepest penetration of the offending pairs after advancing t into the
// step (t in [0, h]); depth_at(0) <= tolerance < depth_at(h) is the bracket. Stops as soon as the
// depth lies within [-tolerance, tolerance] (touching), or after max_iterations.
ImpactSearch findFirstContact(const std::function<double(double)>& depth_at, double h,
                              double depth_at_h, double tolerance, int max_iterations,
                              bool regula_falsi);

}  // namespace tumble
