// The overlays drawn in the scene's space (contacts, forces, velocities), as marks for the
// renderer (render/draw_list.h, DrawMarks), from one frame's record and samples. The scales are
// fixed for the whole clip, so an arrow's length compares across frames; the legend prints them.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/frame_record.h"
#include "dynamics/trajectory.h"
#include "dynamics/world.h"
#include "render/draw_list.h"
#include "scene/overlay_spec.h"

namespace tumble {

struct OverlayScales {
  double length_m = 0.1;       // a body's typical size: the contact normals' length
  double force_n_per_m = 1;    // arrow length: a force of this many N per m of arrow (1, 2 or 5 x 10^k)
  double impulse_ns_per_m = 1; // impacts' impulses, N s per m
  bool impacts = false;        // the clip has impacts (the Baraff model's) to draw
  double speed_s = 1;          // velocity arrows: m of arrow per m/s
  double longest_m = 1;        // force and impulse arrows are cut at this length
};

// From the whole clip: the moving bodies' drawn radii and weights, the largest impulse and speed.
OverlayScales overlayScales(const World& world, const std::vector<double>& radii,
                            const std::vector<FrameRecord>& records, const Trajectory& trajectory,
                            const std::vector<int>& velocity_bodies);

// The bodies whose velocities are drawn: those `spec.bodies` names, or every body that moves.
std::vector<int> velocityBodies(const OverlaySpec& spec, const World& world);

// The marks of one frame. `eye` (m): the camera's position, which arrowheads open towards.
DrawMarks overlayMarks(const OverlaySpec& spec, const OverlayScales& scales, const FrameRecord& record,
                       const std::vector<BodySample>& samples, const std::vector<int>& velocity_bodies,
                       const World& world, const Eigen::Vector3f& eye, int frame_height);

// The marks' colours (sRGB), shared with the legend.
namespace overlay_colour {
inline const Eigen::Vector3f kResting{0.20f, 0.85f, 0.30f};     // resting, friction sticking (or none)
inline const Eigen::Vector3f kSliding{1.00f, 0.85f, 0.10f};     // resting, friction sliding
inline const Eigen::Vector3f kColliding{0.95f, 0.15f, 0.15f};
inline const Eigen::Vector3f kSeparating{0.80f, 0.80f, 0.85f};
inline const Eigen::Vector3f kForce{1.00f, 0.50f, 0.00f};
inline const Eigen::Vector3f kImpulse{0.95f, 0.25f, 0.95f};
inline const Eigen::Vector3f kVelocity{0.25f, 0.55f, 1.00f};
inline const Eigen::Vector3f kTrialApart{0.30f, 0.85f, 1.00f};    // back_step: a trial time still apart
inline const Eigen::Vector3f kTrialDeep{1.00f, 0.35f, 0.30f};     // back_step: a trial time too deep
inline const Eigen::Vector3f kFirstContact{1.00f, 1.00f, 1.00f};  // back_step: the time it found
inline const Eigen::Vector3f kBox{1.00f, 0.90f, 0.35f};           // broad_phase: a piece's box
inline const Eigen::Vector3f kPair{0.10f, 0.95f, 0.75f};          // broad_phase: a candidate pair
}  // namespace overlay_colour

}  // namespace tumble
