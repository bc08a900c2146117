// The scene file's content after loading and validation (schema version 1). Plain data: SI units,
// world z-up. Every field holds its documented default when the file leaves it out.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/settings.h"
#include "geometry/shape_kind.h"
#include "scene/joint_spec.h"
#include "scene/overlay_spec.h"

namespace tumble {

// Where a value was written, so later stages (mesh import) can point at it in their errors.
struct SourceLocation {
  std::string pointer;   // JSON pointer, e.g. "/bodies/2/mesh"
  int line = 0, column = 0;
};

// One primitive of a compound body, placed in the body's frame.
struct PieceSpec {
  ShapeKind shape = ShapeKind::Box;                    // Box, Sphere, Capsule, Cylinder or Cone
  Eigen::Vector3d box_size_m{1, 1, 1};
  double radius_m = 0.5, capsule_length_m = 1, height_m = 1, inner_radius_m = 0.4;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// What the renderer shows of a body: its visual mesh (for a mesh body, the file's meshes with their
// materials; for the built-in shapes, the shape) or its convex collision pieces, for teaching.
enum class BodyDraw { Visual, Hulls };

struct BodySpec {
  std::string name;
  ShapeKind shape = ShapeKind::Box;
  std::filesystem::path mesh;                          // absolute, for ShapeKind::Mesh
  SourceLocation mesh_location;                        // where "mesh" was written
  double mesh_scale = 1;                               // file units -> metres
  Eigen::Vector3d box_size_m{1, 1, 1};                 // full edge lengths, for Box
  double radius_m = 0.5;                               // for Sphere, Capsule, Cylinder and Cone
  double capsule_length_m = 1;                         // the straight part, along the body's z
  double height_m = 1;                                 // for Cylinder, Tube and Cone, along the body's z
  double inner_radius_m = 0.4;                         // a Tube's bore
  std::vector<PieceSpec> pieces;                       // for Compound
  int subdivisions = 3;                                // how finely a smooth shape is drawn
                                                       // (the collision shape is exact)
  bool is_static = false;                              // planes are always static
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero(); // of the shape's origin (mesh file origin)
  SourceLocation position_location;                    // where "position_m" was (or would be) written
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();          // of the centre of mass, world
  Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero(); // world frame
  double density_kg_m3 = 1000;                         // used unless mass_kg is given
  std::optional<double> mass_kg;
  double restitution = 0.5;                            // Newton's coefficient, [0, 1]
  double friction = 0.5;                               // Coulomb coefficient, >= 0
  double youngs_modulus_pa = 1e8;                      // Pa, > 0 (the penalty model's stiffness)
  double poisson_ratio = 0.3;                          // (-1, 0.5)
  Eigen::Vector3d colour_srgb{0.8, 0.45, 0.2};         // 0..1, as a colour picker shows it
  bool colour_given = false;                           // the scene set it: it replaces a mesh file's
                                                       // colours and textures
  std::optional<BodyDraw> draw;                        // unset: the render section's default
};

// A body a camera names ("follow", "fit", an orbit's "target"), and where, for the check that it
// exists once the bodies are read.
struct CameraBodyRef {
  std::string name;
  std::string pointer;                                 // JSON pointer of the name in the file
};

struct CameraSpec {
  // Fixed: a position and a look-at point or orientation. Orbit: about a point or a body, at a
  // distance, yaw and pitch. Follow: a body, from an offset, critically damped. Fit: the whole
  // motion of some bodies, seen from a yaw and pitch.
  enum class Form { Fixed, Orbit, Follow, Fit };
  Form form = Form::Fixed;
  std::string name;                                    // in "cameras"; empty for "camera"
  Eigen::Vector3d position_m{6, -8, 4};
  std::optional<Eigen::Vector3d> look_at_m = Eigen::Vector3d(0, 0, 0.5);
  std::optional<Eigen::Quaterniond> orientation;       // camera looks along its -z, up its +y
  Eigen::Vector3d up{0, 0, 1};
  double fov_y_deg = 45;
  // Orbit, and the direction a Fit camera looks from. yaw 0 puts the camera on the target's -y
  // side (Blender's front view); positive yaw turns it counter-clockwise seen from above; positive
  // pitch raises it.
  Eigen::Vector3d target_m{0, 0, 0.5};
  std::string target_body;                             // orbit this body's centre of mass instead
  double distance_m = 10;                              // m, > 0
  double yaw_deg = 30, pitch_deg = 20;
  // Follow.
  std::string follow_body;
  Eigen::Vector3d offset_m{0, -4, 1};                  // m, world frame, from the body's centre of mass
  double smoothing_s = 0.3;                            // s: the critically damped lag's time constant
  // Fit: these bodies (empty: every body but the ground) over the whole clip.
  std::vector<std::string> fit_bodies;
  std::vector<CameraBodyRef> body_refs;                // every body named above
};

struct DirectionalLightSpec {
  Eigen::Vector3d direction{-0.4, 0.3, -1};            // the way the light travels
  Eigen::Vector3d colour_srgb{1, 1, 1};
  double intensity = 1;
  bool shadows = true;
};

struct LightingSpec {
  std::vector<DirectionalLightSpec> directional;       // at least one
  Eigen::Vector3d ambient_srgb{0.55, 0.57, 0.62};
  double ambient_intensity = 0.35;
};

struct RenderSpec {
  int width = 1280, height = 720;                      // pixels
  int fps = 30;                                        // frames per second
  int frames = 120;                                    // frame k (from 1) shows time (k-1)/fps
  int samples = 4;                                     // MSAA: 1 or 4
  int shadow_map_size = 2048;                          // texels per side
  Eigen::Vector3d background_srgb{0.80, 0.86, 0.93};
  int crf = 23;                                        // H.264 quality
  BodyDraw draw = BodyDraw::Visual;                    // for bodies that do not say
  double time_scale = 1;                               // simulated s per played s (--time-scale): 0.25 is 4x slow motion
};

// The simulation's settings are dynamics/settings.h's, filled straight from the file; a scene
// asks for sleeping unless it says otherwise.
struct SimulationSpec {
  StepSettings step = withSleep(StepSettings{});
  int steps_per_frame = 8;                             // dt = frame interval / steps_per_frame exactly
  Eigen::Vector3d gravity_m_s2{0, 0, -9.81};
  static StepSettings withSleep(StepSettings s) {
    s.sleep.enabled = true;
    return s;
  }
};

struct Scene {
  std::filesystem::path file;                          // the scene file, as given
  std::string name;                                    // file stem: default output names
  int schema_version = 1;
  std::vector<BodySpec> bodies;
  std::vector<JointSpec> joints;                       // "joints" (scene/joint_reader.h)
  CameraSpec camera;                                   // "camera", else the first of "cameras"
  std::vector<CameraSpec> cameras;                     // "cameras": named, picked by --camera
  LightingSpec lighting;
  RenderSpec render;
  SimulationSpec simulation;
  std::optional<std::string> output;                   // default -o, relative to the working dir
  OverlaySpec overlays;                                // "overlays", "overlay_bodies": what is drawn over the frames
  std::string resolved_json;   // the JSON read, after --set and --patch (keys sorted): what provenance hashes
};

}  // namespace tumble
