// Impacts that a neighbour turns back at once. A pair's impact is solved on its own when what it
// sets moving travels on (Newton's cradle: the struck ball leaves, reaches the next and stops;
// impulse_propagation.h). But a light plate between two heavy blocks, struck from above, is sent
// down into the block below, bounces off it, meets the block above again, and so on: the rigid
// model's answer is an infinite sequence of ever faster impacts in a shrinking gap (an inelastic
// collapse: S. McNamara and W. R. Young, "Inelastic collapse in two dimensions", Physical Review E,
// 1994). Back-stepping chased each of them, the sub-steps hit their cap, and the block above went
// through the plate.
//
// The rule: after a pair's impact, if a point of the pair lifts off, and a contact of the pair's
// bodies outside the pair (touching and approaching, or within the detection margin and closing
// within the settle time) would, stopped plastically, bring that point back, then the lift-off
// cannot happen on its own: the pair and those contacts are one impact, solved together with
// their restitution (the unit of simultaneity of impulse_propagation.h, grown by what the
// dynamics say must be simultaneous). A cradle's struck ball, stopped by the next, does not come
// back to the ball that struck it, so the cradle keeps its pair-by-pair answer; a plate pinched
// between two blocks does, and the three bodies take one impact: the block above bounces off the
// plate and the block below together.
#pragma once

#include <vector>

#include "dynamics/baraff/impulse_propagation.h"
#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

// Each moving body's contacts: the island's and those outside it (touching and separating, or
// within the margin), to find a pair's neighbours without going through every contact.
class ContactNeighbours {
 public:
  ContactNeighbours(const World& world, const std::vector<const Contact*>& island,
                    const std::vector<const Contact*>& outside);
  // The contacts of a moving body of `points` that are not in `points`, each once.
  std::vector<const Contact*> around(const World& world, const std::vector<const Contact*>& points) const;

 private:
  std::vector<std::vector<const Contact*>> by_body_;
};

// Resolves the impact on `points` (resolveImpact, restitution as given), grown while the lift-offs
// it leaves would be turned back at once by contacts in `neighbours` (see above): those join it
// and the impact is solved again from the state before it. `within_s`: how soon a gap must close
// to count (the settle rule's time). Returns whether it grew (bodies beyond the pair's moved).
bool resolveImpactWithNeighbours(World& world, const std::vector<const Contact*>& points,
                                 const std::vector<const Contact*>& neighbours, const ContactSettings& s,
                                 const BounceThreshold& min_bounce_speed, double restitution_scale, const SettleRule& settle,
                                 ContactSolveStats& stats);

}  // namespace tumble
