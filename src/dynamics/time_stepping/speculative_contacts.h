// Which speculative contacts of separated pieces closest at a vertex or an edge's end may act.
//
// A speculative contact asks that its gap not close past zero within the step: v_n >= -gap/dt
// along its normal (contact_impulses.h). That is exact for a face and what faces it, whose normal
// stays put as they move. Pieces closest at a vertex or an edge's end (a tetrahedron falling past
// a box's top edge with 0.5 mm to spare) have a normal that turns as they move: at the step before
// they pass, it points nearly along the motion, and the row stops a body that would have gone by
// untouched (the solver pushes it at that edge, it spins and lands crooked). Speculative contacts
// in Box2D and Jolt share this ghost; they keep it small with a fixed speculative distance of a
// few centimetres, which a fast body outruns.
//
// Here each such contact is followed through the step along the bodies' free motion (velocities
// after the applied impulses, spins as they are) by conservative advancement (first_touch.h): a
// pair that stays apart gives no row; a pair that meets gets its row at the first touch, along the
// direction between the closest points there, with the gap that direction shows at the start of
// the step. A pair pushed toward each other by some other contact within the step meets without a
// row: it may end the step overlapping by what that push added, and the next step's projection
// and rows take it from there.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_detection.h"
#include "dynamics/world.h"

namespace tumble {

// Drops the contacts (and their pairs, kept aligned) of pieces closest at a vertex or an edge's end,
// apart by more than `tolerance` (m), that do not meet within `dt` moving freely (under gravity if
// `gravity`); moves the others to where they first meet. Returns how many were dropped.
long keepReachableContacts(const World& world, const ContactDetector& detector, std::vector<Contact>& contacts,
                           std::vector<PiecePair>& pairs, double dt, bool gravity, double tolerance);

// Pieces spinning fast enough to sweep more than `margin` (m) in the step may bring a feature the
// pair's manifold does not hold (built on the features closest now) into the other within the
// step: a spike toppling off a ridge swings a base corner onto it. Each such pair is also
// collided where its free motion ends the step; a point found there deeper than `tolerance`, apart
// at the start by more than it and not near a contact the pair has, becomes a speculative contact
// of its own (carried back to the start, along the normal found at the end). Where a point found
// there lies behind that normal at the start (the corner came in across it), the pair is collided
// at earlier instants of the motion instead, and the first that shows an overlap gives the
// contacts. Returns how many.
// `spin`: each body's angular velocity now (bodySpins).
// The pairs are collided on `threads` threads; what is added, and its order, does not depend on it.
long addSweptContacts(const World& world, const ContactDetector& detector, std::vector<Contact>& contacts,
                      std::vector<PiecePair>& pairs, const std::vector<Eigen::Vector3d>& spin, double dt, bool gravity,
                      double margin, double tolerance, int threads = 1);

}  // namespace tumble
