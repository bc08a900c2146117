// Sleeping (docs/architecture.md: "bodies at rest sleep"). An island of moving bodies that has stayed slower
// than a speed and a spin threshold for a while, and rests on something fixed, is frozen: its
// momenta are zeroed and, to every stage of the step, its bodies are static — not integrated, no
// gravity, no contact rows, and no narrow phase between two of them or with the ground. Anything
// awake that comes into contact with one of its bodies (within the detection margin) wakes the
// whole island before the contact is solved, so an awake body never meets a frozen one in a solve.
//
// Why: a settled pile costs nothing, and it does not creep or jitter in the render. Why not always:
// a frozen body is exactly still, which is a model, not the solver's answer; `"sleep": false` in
// the scene (or --no-sleep) shows what the contact solve alone does.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

class ContactDetector;

struct SleepCounters {
  long islands_slept = 0, islands_woken = 0;
  int asleep_now = 0;   // bodies asleep after the last step
};

class SleepKeeper {
 public:
  explicit SleepKeeper(const World& world);

  // Wakes every sleeping island one of whose bodies is in a contact of `contacts` with an awake
  // moving body. Returns true if any woke: their contacts with the ground and with each other
  // were not detected, so the caller detects again.
  bool wakeTouched(World& world, const std::vector<Contact>& contacts, ContactDetector& detector);

  // After a step of dt: counts how long each awake moving body has been quiet, and puts to sleep
  // every island (bodies joined by `contacts`) whose bodies have all been quiet for `after_s` and
  // that touches something fixed. Returns true if any island fell asleep.
  bool settle(World& world, const std::vector<Contact>& contacts, const SleepSettings& settings,
              double dt, ContactDetector& detector);

  const SleepCounters& counters() const { return counters_; }

 private:
  void freeze(World& world, int body, int island, ContactDetector& detector);
  void wake(World& world, int island, ContactDetector& detector);
  int find(int body);

  std::vector<double> quiet_s_;            // how long each body has been below the thresholds
  std::vector<int> island_;                // sleeping island of each body; -1 when awake
  std::vector<double> inv_mass_;           // restored on waking
  std::vector<Eigen::Vector3d> inv_inertia_;
  std::vector<int> parent_;                // union-find over bodies (settle)
  std::vector<char> supported_, restless_;   // per body, then per island at its root
  std::vector<int> id_of_root_;               // sleeping island given to each root (settle)
  int next_island_ = 0;
  SleepCounters counters_;
};

}  // namespace tumble
