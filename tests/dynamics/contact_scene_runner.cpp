#include "contact_scene_runner.h"

#include <algorithm>

#include "collision/collision_hull.h"
#include "collision/narrow_phase.h"
#include "dynamics/body_extent.h"
#include "dynamics/contact_detection.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

namespace tumble::test {

double worldPenetration(const World& world) {
  double deepest = 0;
  // Bodies whose bounding spheres (about the centre of mass) are apart cannot overlap: the
  // separating-axis test of every pair would cost a 100-stone arch more than its simulation.
  const std::vector<BodyExtent> extents = extentsOf(world);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& a = world.bodies[i];
    if (a.shape == ShapeKind::Plane) continue;
    for (const ConvexPiece& pa : a.pieces) {
      CollisionHull ha = makeCollisionHull(pa);
      for (std::size_t j = 0; j < world.bodies.size(); ++j) {
        const RigidBody& b = world.bodies[j];
        // Sleeping bodies are static only for the while: their overlaps count.
        if (j == i || (a.fixedByScene() && b.fixedByScene())) continue;
        if (b.shape == ShapeKind::Plane) {
          deepest = std::max(deepest, -groundSeparation(pa, poseOf(a), b.x.z()));
          continue;
        }
        if (j < i || (a.x - b.x).norm() > extents[i].radius + extents[j].radius) continue;
        for (const ConvexPiece& pb : b.pieces) {
          SatCache cache;
          // For overlapping convex pieces the SAT value is minus the penetration depth.
          deepest = std::max(deepest, -separation(ha, poseOf(a), makeCollisionHull(pb), poseOf(b), cache));
        }
      }
    }
  }
  return deepest;
}

SceneRun runScene(const std::string& name, double seconds,
                  const std::function<void(const World&)>& on_step, int penetration_every,
                  const std::function<void(Scene&)>& edit, bool keep_going) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  // These tests hold the contact solve itself to its acceptance thresholds: sleeping would freeze
  // whatever it reached. A test that is about sleeping turns it back on in `edit`.
  scene.simulation.step.sleep.enabled = false;
  if (edit) edit(scene);
  setDuration(scene, seconds);
  scene.render.frames += 1;   // frame k is at (k-1)/fps: one more frame reaches `seconds`
  BuiltWorld built = buildWorld(scene);
  SceneRun run;
  SimulationPlan plan{built.step, scene.simulation.steps_per_frame, scene.render.frames};
  plan.keep_going = keep_going;
  Simulator sim(std::move(built.world), plan);
  long step = 0;
  run.trajectory = sim.run({}, [&](const World& w) {
    if (++step % penetration_every == 0) run.max_penetration = std::max(run.max_penetration, worldPenetration(w));
    if (on_step) on_step(w);
  });
  run.max_penetration = std::max(run.max_penetration, worldPenetration(sim.world()));
  run.counters = sim.pipeline().counters();
  run.faults = sim.faults().total();
  if (sim.faults().first()) run.first_fault = sim.faults().first()->describe();
  return run;
}

}  // namespace tumble::test
