#include "app/render_dry_run.h"

#include <filesystem>

#include "app/camera_rig.h"

namespace tumble {

void printDryRun(const DryRun& plan, std::FILE* out) {
  const Scene& s = plan.scene;
  const RenderSpec& r = s.render;
  const bool video = plan.target.kind == OutputTarget::Kind::Video;
  std::fprintf(out, "scene     %s\n", s.file.string().c_str());
  std::fprintf(out, "render    %dx%d, %d fps, %d frames in the clip, %dx MSAA, shadow map %d^2%s\n", r.width, r.height,
               r.fps, r.frames, r.samples, r.shadow_map_size, video ? (", crf " + std::to_string(r.crf)).c_str() : "");
  std::fprintf(out, "simulate  step %.9g s, %d steps per frame\n", s.simulation.step.dt, s.simulation.steps_per_frame);
  std::fprintf(out, "camera    %s%s%s%s\n", cameraFormName(plan.camera.form), plan.camera.name.empty() ? "" : " (--camera ",
               plan.camera.name.c_str(), plan.camera.name.empty() ? "" : ")");
  std::fprintf(out, "output    %s %s\n", video ? "video" : "PNG", plan.target.path.string().c_str());
  std::fprintf(out, "frames    %zu\n", plan.frames.size());
  // The instant a frame shows is the simulator's: (k - 1) frame intervals of whole steps.
  const double interval = s.simulation.steps_per_frame * s.simulation.step.dt;
  for (int k : plan.frames) {
    const std::filesystem::path file = framePath(plan.target, k);
    std::error_code ec;
    const bool exists = std::filesystem::exists(file, ec);
    if (video) {
      std::fprintf(out, "  %6d  t = %.9g\n", k, (k - 1) * interval);
      continue;
    }
    std::fprintf(out, "  %6d  t = %-12.9g %s%s\n", k, (k - 1) * interval, file.string().c_str(),
                 exists ? (plan.overwrite ? "  (exists: would be replaced)" : "  (exists: refused without -y)") : "");
  }
  std::error_code ec;
  if (video && std::filesystem::exists(plan.target.path, ec))
    std::fprintf(out, "          %s exists: %s\n", plan.target.path.string().c_str(),
                 plan.overwrite ? "would be replaced" : "refused without -y");
  std::fprintf(out, "dry run: nothing simulated, rendered or written\n");
}

}  // namespace tumble
