// What the overlays draw of one rendered frame, recorded while the simulation runs: the contacts in
// force at the frame's instant (point, normal, whether they separate, rest or collide, whether
// friction sticks or slides, and the force each carried over the last step where the model keeps
// it), the impacts resolved since the frame before, and the energy.
//
// Recording never changes the motion. The recorder finds contacts with a detector of its own (its
// caches are not the pipeline's) on a copy of the world's state in which sleeping bodies count as
// moving, so that a stack gone to sleep still shows its contacts; it reads the model's impulse
// memory through const access, and the impact log (SharedStages::impact_log) only reads the state
// around the impulses.
// tests/dynamics/test_frame_record.cpp compares every step's state bit for bit with and without it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_detection.h"
#include "dynamics/pipeline.h"
#include "dynamics/settings.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

enum class ContactState { Separating, Resting, Colliding };
enum class FrictionState { None, Sticking, Sliding };

struct RecordedContact {
  int a = -1, b = -1;                                  // bodies, as in Contact
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     // m, world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit, from A to B
  double depth = 0;                                    // m, > 0 penetrating
  ContactState state = ContactState::Resting;          // by the normal relative velocity
  FrictionState friction = FrictionState::None;        // None: frictionless pair, or separating
  bool has_force = false;                              // the model kept this contact's impulse
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     // N on B, world: last step's impulse / dt
};

struct FrameRecord {
  double time = 0;                       // s
  std::vector<RecordedContact> contacts;
  std::vector<ImpactMark> impacts;       // resolved since the frame before (event-driven models)
  double kinetic = 0, potential = 0;     // J; potential: gravity's, plus what contacts store
  double deepest_m = 0;                  // m, the deepest contact (0 when none overlaps)
  double total() const { return kinetic + potential; }
};

// The energy of the world now: kinetic (translation and rotation) and gravitational, J.
void worldEnergy(const World& world, double& kinetic, double& potential);

class FrameRecorder {
 public:
  // `world`: the world as the simulation starts (its bodies' shapes are copied once).
  FrameRecorder(const World& world, const StepSettings& settings);
  FrameRecorder(const FrameRecorder&) = delete;   // the detector points into `awake_`
  FrameRecorder& operator=(const FrameRecorder&) = delete;
  // The frame at the world's present state. `impacts` (moved from) are those since the last frame.
  FrameRecord record(const World& world, const Pipeline& pipeline, std::vector<ImpactMark>& impacts);

 private:
  World awake_;                 // the world's state, sleepers moving (declared before the detector)
  ContactDetector detector_;
  ContactSettings contact_;
  std::vector<Contact> found_;
};

}  // namespace tumble
