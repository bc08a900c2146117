#include "app/frame_provenance.h"

#include <cstdio>

#include "base/build_info.h"

namespace tumble {

Provenance frameProvenance(const Scene& scene, const std::string& camera) {
  // The flags (--fps, --dt, --size, ...) change the Scene, not its JSON: what they resolved to is
  // hashed with it. %.17g reads back to the same double, so equal settings hash equal.
  const RenderSpec& r = scene.render;
  const SimulationSpec& s = scene.simulation;
  char settings[512];
  std::snprintf(settings, sizeof settings,
                "\nsize %dx%d fps %d frames %d samples %d shadow %d crf %d dt %.17g steps %d integrator %d "
                "model %d sleep %d camera %s",
                r.width, r.height, r.fps, r.frames, r.samples, r.shadow_map_size, r.crf, s.step.dt, s.steps_per_frame,
                static_cast<int>(s.step.integrator), static_cast<int>(s.step.model), s.step.sleep.enabled ? 1 : 0,
                camera.c_str());
  Provenance p;
  p.version = buildVersion();
  p.commit = buildCommit();
  p.scene_hash = contentHash(scene.resolved_json + settings);
  p.frame_interval_s = s.steps_per_frame * s.step.dt;   // simulated: --time-scale shrinks it
  return p;
}

}  // namespace tumble
