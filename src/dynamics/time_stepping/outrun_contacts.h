// Contacts for the motion a step's solve gives, where it outruns the motion they were detected for.
//
// The step's contacts are found within each body's reach: how far it can travel in the step at
// the speeds it had (time_stepping_model.h). An impact can give a body far more: a 17 kg block
// falling at 10 m/s onto the end of a 4 kg plate lying on a ramp (an untuned scene) set the plate
// spinning at 55 rad/s, its far end swinging 5 cm within the 1/240 s step into the ramp, where
// the step held no contact; it ended the step 3.1 cm deep and the drift projection pushed it out
// by as much, a jump the run-time fault check reports (a body moved farther than its speeds allow).
// Where a body's speeds after the solve carry it past its reach by more than kOutrunShare of its
// thinnest piece (at least the margin), the step detects again, out to the farther of the two
// reaches and along the new motion (the swept and the reachable speculative contacts of
// speculative_contacts.h), and adds what it finds that the step's contacts lack; the caller
// solves the step again from its start with them.
#pragma once

#include <utility>
#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/contact.h"
#include "dynamics/contact_detection.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

// How far past its reach a body may be sent before the step is solved again, as a share of its
// thinnest piece (at least the margin): an overlap that shallow the drift projection takes out at
// the step's end within what the fault check allows a correction (half the thinnest piece), and a
// share of the body's own size keeps the rule the same at every scale. Past the margin alone, a
// pile's landings had 15 % of the 100-box pile's steps solved twice.
inline constexpr double kOutrunShare = 0.25;

// Whether some body's speeds now sweep it farther in `dt` than its `reach` (m) plus the larger of
// the margin and kOutrunShare of its thinnest piece.
bool outrunsReach(const World& world, const std::vector<BodyExtent>& extents, const std::vector<double>& reach,
                  double dt, double margin);

class OutrunContacts {
 public:
  // Appends to `contacts` the contacts of the world's current poses within the larger of `reach`
  // and the current speeds' reach, kept or swept along the current speeds, that are not within
  // the margin of a contact `contacts` already has between the same two bodies. `reach` is
  // raised to that larger reach. Returns how many were added.
  long add(const World& world, ContactDetector& detector, const StepSettings& settings,
           const std::vector<double>& body_radius, bool gravity, std::vector<double>& reach,
           std::vector<Contact>& contacts);

 private:
  std::vector<double> reach_now_;
  std::vector<Eigen::Vector3d> spin_;
  std::vector<Contact> found_;
  std::vector<PiecePair> pairs_;
  std::vector<std::pair<long long, std::size_t>> known_;   // (body pair, index) of the step's contacts
};

}  // namespace tumble
