#include "contact_scene_runner.h"

#include <algorithm>
#include <vector>

#include "collision/aabb.h"
#include "collision/collision_hull.h"
#include "collision/narrow_phase.h"
#include "dynamics/contact_detection.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

namespace tumble::test {

double worldPenetration(const World& world) {
  // Every piece's hull and box once: in a pile of a hundred bodies most pairs are far apart, and
  // two pieces whose boxes are disjoint cannot overlap, so skipping them leaves the answer exact.
  struct Placed {
    std::size_t body;
    CollisionHull hull;
    Eigen::Isometry3d pose;
    Aabb box;
  };
  std::vector<Placed> placed;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& a = world.bodies[i];
    if (a.shape == ShapeKind::Plane) continue;
    for (const ConvexPiece& p : a.pieces) placed.push_back({i, makeCollisionHull(p), poseOf(a), aabbOf(p, poseOf(a), 0)});
  }
  double deepest = 0;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const Placed& pa = placed[k];
    const RigidBody& a = world.bodies[pa.body];
    for (const RigidBody& g : world.bodies) {
      // Sleeping bodies are static only for the while: their overlaps count.
      if (g.shape != ShapeKind::Plane || (a.fixedByScene() && g.fixedByScene())) continue;
      deepest = std::max(deepest, -groundSeparation(*pa.hull.piece, pa.pose, g.x.z()));
    }
    for (std::size_t m = k + 1; m < placed.size(); ++m) {
      const Placed& pb = placed[m];
      const RigidBody& b = world.bodies[pb.body];
      if (pb.body == pa.body || (a.fixedByScene() && b.fixedByScene()) || !overlaps(pa.box, pb.box)) continue;
      SatCache cache;
      // For overlapping convex pieces the SAT value is minus the penetration depth.
      deepest = std::max(deepest, -separation(pa.hull, pa.pose, pb.hull, pb.pose, cache));
    }
  }
  return deepest;
}

void EnergyRise::add(const World& world) {
  double kinetic = 0, potential = 0;
  for (const RigidBody& b : world.bodies) {
    if (b.is_static) continue;
    kinetic += b.kineticEnergy();
    potential -= b.mass * world.gravity.dot(b.x);
  }
  largest_kinetic_ = std::max(largest_kinetic_, kinetic);
  low_potential_ = std::min(low_potential_, potential);
  high_potential_ = std::max(high_potential_, potential);
  const double total = kinetic + potential, scale = largest_kinetic_ + (high_potential_ - low_potential_);
  if (scale > 0 && total > lowest_) largest_ = std::max(largest_, (total - lowest_) / scale);
  lowest_ = std::min(lowest_, total);
}

SceneRun runScene(const std::string& name, double seconds,
                  const std::function<void(const World&)>& on_step, int penetration_every,
                  const std::function<void(Scene&)>& edit, bool keep_going) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  // These tests hold the contact solve itself to its acceptance thresholds: sleeping would freeze
  // whatever it reached. A test that is about sleeping turns it back on in `edit`.
  scene.simulation.step.sleep.enabled = false;
  if (edit) edit(scene);
  setDuration(scene, seconds);   // the last frame shows `seconds`
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
