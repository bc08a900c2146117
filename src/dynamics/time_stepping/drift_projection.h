// Drift projection for the time-stepping model: one push per pair of bodies, by its deepest point,
// in inverse proportion to mass, positions only, repeated in passes (tuning::kProjectionPasses),
// each pass reading the depths the earlier pushes left (a contact's depth changes by the relative
// displacement of its two bodies along its normal). One pass, as the Baraff model makes after
// every sub-step, cannot keep up under a load: in a column of boxes each push down into the box
// below is undone by the push up from it, and in the 1000-box pile pairs sank into each other by
// 6-8 cm over seconds.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_islands.h"
#include "dynamics/world.h"

namespace tumble {

class DriftProjection {
 public:
  // Moves the bodies of `contacts` deeper than `tolerance_m` out, and updates every contact's
  // depth to the bodies' new positions (the solve goes on with these contacts). Returns the
  // number of pushes.
  long project(World& world, std::vector<Contact>& contacts, double tolerance_m);

 private:
  std::vector<Eigen::Vector3d> moved_;   // each body's displacement in this projection
  BodyPairGroups grouped_;               // kept between steps: reused buffers
};

}  // namespace tumble
