// tumble check SCENE: validates the scene and says what would be simulated and rendered.
#include <cstdio>
#include <memory>

#include "app/camera_rig.h"
#include "app/commands.h"
#include "app/scene_options.h"
#include "dynamics/pipeline.h"
#include "scene/scene_overrides.h"
#include "scene/world_builder.h"

namespace tumble {
namespace {

const char* shapeName(ShapeKind s) {
  switch (s) {
    case ShapeKind::Mesh: return "mesh";
    case ShapeKind::Box: return "box";
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Capsule: return "capsule";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::Tube: return "tube";
    case ShapeKind::Cone: return "cone";
    case ShapeKind::Compound: return "compound";
    case ShapeKind::Plane: return "plane";
  }
  return "?";
}

void printBodies(const Scene& scene, const World& world) {
  int moving = 0;
  for (const RigidBody& b : world.bodies) moving += b.is_static ? 0 : 1;
  std::printf("bodies    %zu (%d moving, %zu static)\n", world.bodies.size(), moving,
              world.bodies.size() - moving);
  std::printf("  %-16s %-8s %6s %10s  %-32s %s\n", "name", "shape", "pieces", "mass_kg",
              "principal inertia kg m^2", "centre of mass m");
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    char mass[32], inertia[64], com[64];
    std::snprintf(mass, sizeof mass, b.shape == ShapeKind::Plane ? "-" : "%.6g", b.mass);
    std::snprintf(inertia, sizeof inertia, b.shape == ShapeKind::Plane ? "-" : "(%.4g, %.4g, %.4g)",
                  b.inertia_body.x(), b.inertia_body.y(), b.inertia_body.z());
    std::snprintf(com, sizeof com, "(%.4g, %.4g, %.4g)", b.x.x(), b.x.y(), b.x.z());
    std::printf("  %-16s %-8s %6zu %10s  %-32s %s%s\n", b.name.c_str(), shapeName(b.shape),
                b.pieces.size(), mass, inertia, com, b.is_static ? "  static" : "");
    if (scene.bodies[i].shape == ShapeKind::Mesh) {
      // What the picture shows of it: the file as it is, or the convex pieces that collide.
      const bool hulls = scene.bodies[i].draw.value_or(scene.render.draw) == BodyDraw::Hulls;
      std::printf("  %-16s mesh %s, drawn %s%s\n", "", scene.bodies[i].mesh.string().c_str(),
                  hulls ? "as its collision hulls" : "as the file holds it",
                  !hulls && scene.bodies[i].colour_given ? " in the scene's colour" : "");
    }
  }
}

// The default camera's form, and the named ones --camera picks from.
void printCameras(const Scene& scene) {
  std::printf("camera    %s", cameraFormName(scene.camera.form));
  if (!scene.camera.follow_body.empty()) std::printf(" \"%s\"", scene.camera.follow_body.c_str());
  std::printf("\n");
  for (const CameraSpec& c : scene.cameras) std::printf("  --camera %-16s %s\n", c.name.c_str(), cameraFormName(c.form));
}

int run(const SceneOptions& o) {
  Scene scene = loadSceneWithOverrides(o);
  BuiltWorld built = buildWorld(scene);
  for (const std::string& w : built.warnings) std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
  const RenderSpec& r = scene.render;
  std::printf("scene     %s (schema version %d): valid\n", scene.file.string().c_str(), scene.schema_version);
  printBodies(scene, built.world);
  std::printf("pipeline  step %.6g s (%d per frame), gravity (%g, %g, %g) m/s^2\n", scene.simulation.step.dt,
              scene.simulation.steps_per_frame, scene.simulation.gravity_m_s2.x(),
              scene.simulation.gravity_m_s2.y(), scene.simulation.gravity_m_s2.z());
  for (const std::string& line : Pipeline(built.world, built.step).describe(built.step)) std::printf("  %s\n", line.c_str());
  std::printf("render    %dx%d, %d fps, %d frames (t = 0 .. %.3f s), %dx MSAA, shadow map %d^2, %zu directional light(s)\n",
              r.width, r.height, r.fps, r.frames, durationOfFrames(r.frames, r.fps), r.samples, r.shadow_map_size,
              scene.lighting.directional.size());
  printCameras(scene);
  std::printf("output    %s\n", scene.output.value_or("out/" + scene.name + ".mp4").c_str());
  if (scene.overlays.any()) {
    std::string kinds;
    for (OverlayKind k : scene.overlays.kinds) kinds += (kinds.empty() ? "" : ", ") + overlayName(k);
    std::printf("overlays  %s\n", kinds.c_str());
    for (const std::string& b : scene.overlays.bodies) std::printf("  velocities of %s\n", b.c_str());
  }
  return 0;
}

}  // namespace

std::function<int()> addCheckCommand(CLI::App& app) {
  auto o = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand("check", "Validate a scene and print what would be simulated and rendered");
  addSceneOptions(*cmd, *o);
  return [o] { return run(*o); };
}

}  // namespace tumble
