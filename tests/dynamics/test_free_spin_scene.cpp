// scenes/free_spin.json (benchmark S5) through the scene file and the simulator: energy and
// angular momentum stay constant through the intermediate-axis flips.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

using namespace tumble;

TEST_CASE("free spin scene conserves energy and |L| with RK4", "[dynamics]") {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/free_spin.json");
  // The acceptance bounds: 1e-6 at dt = 1/600 and 1e-4 at dt = 1/240 (relative, over 10 s).
  for (auto [dt, bound] : {std::pair{1.0 / 600, 1e-6}, std::pair{1.0 / 240, 1e-4}}) {
    INFO("dt = " << dt);
    setTimeStep(scene, dt, "test");
    BuiltWorld built = buildWorld(scene);
    const double E0 = built.world.bodies[1].kineticEnergy(), L0 = built.world.bodies[1].L.norm();
    double dE = 0, dL = 0;
    Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
    sim.run({}, [&](const World& w) {
      dE = std::max(dE, std::abs(w.bodies[1].kineticEnergy() / E0 - 1));
      dL = std::max(dL, std::abs(w.bodies[1].L.norm() / L0 - 1));
    });
    CHECK(dE < bound);
    CHECK(dL < 1e-12);
  }
}
