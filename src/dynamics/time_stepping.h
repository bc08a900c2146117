// The time-stepping contact model (Moreau; Stewart and Trinkle 1996; seed 004 "non-smooth time
// stepping"; seed 003, PGS with friction): one velocity-level impulse problem per step instead of
// going back to each first contact. For each contact with gap phi = -depth (contacts are found
// within a speculative margin, so phi > 0 for pairs about to touch):
//
//   normal    v_n+ >= -max(phi, 0) / dt     a gap may close within the step, never overshoot;
//             v_n+ >= e u                   a touching contact that approached at u bounces
//   friction  two tangent rows, |p_t| <= mu p_n each (a friction pyramid), v_t+ = 0 while inside
//
// solved by projected Gauss-Seidel over the rows (row_gauss_seidel.h) warm-started from the last
// step's impulses (impulse_memory.h). Penetration is not pushed apart by velocity (Baumgarte adds
// energy); the pipeline projects positions instead, as the Baraff model does.
//
// Restitution with a speculative margin: a landing whose gap closes during the step arrives at
// phi = 0 with the small speed that just closes it; its approach speed u is remembered and the
// bounce e u is given the next step, when the contact touches. The bounce is therefore one step
// late (first order in dt), as every quantity of this model is.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solver.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/step_settings.h"
#include "dynamics/world.h"

namespace tumble {

class TimeStepper {
 public:
  // Applies this step's contact impulses to the momenta of `world`, whose velocities already hold
  // the step's applied impulses (gravity). `approach` is each contact's normal approach speed
  // (m/s, > 0 closing) before those, the speed a bounce reverses. Impacts slower than
  // `min_bounce_speed` get no restitution (Pipeline says why).
  void applyContactImpulses(World& world, const std::vector<Contact>& contacts,
                            const std::vector<double>& approach, const StepSettings& settings,
                            double min_bounce_speed, ContactSolveStats& stats);


 private:
  ImpulseMemory memory_;
  std::vector<Eigen::Vector3d> velocity_, spin_;   // per body, this step (reused buffers)
};

// How far each body's points can travel within a step (m; 0 for static bodies): the speculative
// margin the detector adds for it, so that every pair that can touch during the step is a contact
// at its start. (|v| + |g| dt + |w| r) dt, with r the body's radius about its centre of mass.
void bodyReach(const World& world, const std::vector<double>& body_radius, double dt, std::vector<double>& reach);

}  // namespace tumble
