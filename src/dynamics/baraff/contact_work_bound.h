// Contact forces do no positive work. Over a sub-step, the resting contacts' normal forces act
// where the normal velocity is zero and their friction against the slip, so in an island of
// touching bodies the total energy (kinetic plus gravitational) can only fall while they are
// integrated. The integrator holds each force constant over the sub-step, and where friction
// stops a light body's slip well within it (a 60 g plate pinched under a 53 kg block: hundreds of
// newtons on it, 5000 m/s^2) the constant force carries on past the stop and drives the slip the
// other way: such a plate spun up to 50 rad/s and its island gained 2 J in half a millisecond.
// What an island gains over a sub-step is that error, and it is taken back from the island's
// kinetic energy (energy_payment.h), as the drift correction pays for its lifts.
#pragma once

#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

class ContactWorkBound {
 public:
  // Before the sub-step's integration: the islands of `contacts` touching within `tolerance_m`,
  // and each island's energy.
  void before(const World& world, const std::vector<Contact>& contacts, double tolerance_m,
              const std::vector<BodyExtent>& extents);
  // After it (and after any back-step): takes from each island what it gained beyond rounding.
  // Returns how many islands paid.
  int after(World& world) const;

 private:
  std::vector<std::vector<int>> islands_;   // moving bodies
  std::vector<double> energy_, slack_;      // J, per island
};

}  // namespace tumble
