// What the overlays draw of one rendered frame, recorded while the simulation runs: the contacts in
// force at the frame's instant (point, normal, whether they separate, rest or collide, whether
// friction sticks or slides, and the force each carried over the last step where the model keeps
// it), the impacts resolved since the frame before, and the energy; when asked for, the Baraff
// model's back-steps since the frame before (back_step_log.h) and the broad phase's boxes and
// candidate pairs.
//
// Recording never changes the motion. The recorder finds contacts with a detector of its own (its
// caches are not the pipeline's) on a copy of the world's state in which sleeping bodies count as
// moving, so that a stack gone to sleep still shows its contacts; it reads the model's impulse
// memory through const access, and the impact log (SharedStages::impact_log) only reads the state
// around the impulses; the back-step log copies poses the search integrated to; the broad phase is
// read through const access to the pipeline's detector, as its last sweep in the step left it.
// tests/dynamics/test_frame_record.cpp compares every step's state bit for bit with and without it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/back_step_log.h"
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

// One piece's box in the broad phase (m, world): grown by the detection margin, and under the
// time-stepping and penalty models by how far its body can travel in the step. Floats: drawn only.
struct RecordedBox {
  int body = -1;
  Eigen::Vector3f min = Eigen::Vector3f::Zero(), max = Eigen::Vector3f::Zero();
};

// The broad phase as the frame's last step left it: every piece's box and the pairs of pieces whose
// boxes overlap (candidates for the narrow phase; static-static and same-body pairs never are).
struct BroadPhaseRecord {
  std::vector<RecordedBox> boxes;         // per piece
  std::vector<std::pair<int, int>> pairs; // indices into boxes
};

struct FrameRecordOptions {
  bool broad_phase = false;   // keep BroadPhaseRecord (its size grows with the pieces: off by default)
};

struct FrameRecord {
  double time = 0;                       // s
  std::vector<RecordedContact> contacts;
  std::vector<ImpactMark> impacts;       // resolved since the frame before (event-driven models)
  double kinetic = 0, potential = 0;     // J; potential: gravity's, plus what contacts store
  double deepest_m = 0;                  // m, the deepest contact (0 when none overlaps)
  std::vector<BackStepMark> back_steps;  // since the frame before, the last BackStepLog keeps
  BroadPhaseRecord broad_phase;          // with FrameRecordOptions::broad_phase
  double total() const { return kinetic + potential; }
};

// The energy of the world now: kinetic (translation and rotation) and gravitational, J.
void worldEnergy(const World& world, double& kinetic, double& potential);

class FrameRecorder {
 public:
  // `world`: the world as the simulation starts (its bodies' shapes are copied once).
  FrameRecorder(const World& world, const StepSettings& settings, FrameRecordOptions options = {});
  FrameRecorder(const FrameRecorder&) = delete;   // the detector points into `awake_`
  FrameRecorder& operator=(const FrameRecorder&) = delete;
  // The frame at the world's present state. `impacts` (moved from) are those since the last frame,
  // and so are the back-steps `back_steps` holds (taken from it, when given).
  FrameRecord record(const World& world, const Pipeline& pipeline, std::vector<ImpactMark>& impacts,
                     BackStepLog* back_steps = nullptr);

 private:
  World awake_;                 // the world's state, sleepers moving (declared before the detector)
  ContactDetector detector_;
  ContactSettings contact_;
  FrameRecordOptions options_;
  std::vector<Contact> found_;
};

}  // namespace tumble
