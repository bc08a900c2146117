// The Baraff model's tunnelling bound (conservative advancement): how long a sub-step may be so
// that no pair of pieces can pass through each other unseen within it.
#pragma once

#include <vector>

#include "dynamics/contact_detection.h"
#include "dynamics/integrator.h"
#include "dynamics/world.h"

namespace tumble {

class TunnellingBound {
 public:
  // The longest sub-step, at most h, for the world now under `wrenches` (the applied and resting
  // forces of the sub-step); `body_radius` is each body's farthest vertex from its centre of mass,
  // `min_thickness` the thinnest piece of any body.
  double limit(const World& world, const std::vector<Wrench>& wrenches, const std::vector<double>& body_radius,
               double min_thickness, ContactDetector& detector, double h);

 private:
  std::vector<double> speed_, reach_;   // per body: point-speed bound, and how far that reaches in h
  std::vector<ContactDetector::NearPair> near_;
};

}  // namespace tumble
