#include "app/overlay_render.h"

#include <algorithm>
#include <cstdio>

#include "app/back_step_marks.h"
#include "app/broad_phase_marks.h"
#include "app/energy_inset_panel.h"
#include "app/energy_plot_file.h"
#include "app/overlay_text.h"
#include "base/error.h"
#include "render/camera_matrices.h"
#include "render/overlay_composite.h"

namespace tumble {

OverlayRender::OverlayRender(const Scene& scene, OverlaySpec spec) : scene_name_(scene.name), spec_(std::move(spec)) {}

void OverlayRender::checkMotionSource(bool from_trajectory) const {
  if (!from_trajectory) return;
  for (OverlayKind k : spec_.kinds)
    if (k != OverlayKind::Velocities)
      throw Error(ExitCode::Usage, "overlay " + overlayName(k) + " needs the simulation's contacts and energy, "
                                   "which a trajectory file does not hold; only velocities can be drawn with "
                                   "--from-trajectory");
}

void OverlayRender::attach(Simulator& simulator, const StepSettings& settings) {
  if (!any()) return;
  recorder_.emplace(simulator.world(), settings, FrameRecordOptions{spec_.has(OverlayKind::BroadPhase)});
  simulator.setImpactLog(&impacts_);
  if (spec_.has(OverlayKind::BackStep)) simulator.setBackStepLog(&back_steps_);
}

void OverlayRender::onFrame(const Simulator& simulator) {
  if (recorder_)
    records_.push_back(recorder_->record(simulator.world(), simulator.pipeline(), impacts_,
                                         spec_.has(OverlayKind::BackStep) ? &back_steps_ : nullptr));
}

void OverlayRender::prepare(const World& world, const SceneDrawing& drawing, const Trajectory& trajectory,
                             const std::string& model, double dt_s) {
  if (!any()) return;
  world_ = &world;
  velocity_bodies_ = velocityBodies(spec_, world);
  scales_ = overlayScales(world, bodyRadii(drawing), records_, trajectory, velocity_bodies_);
  model_ = model;
  dt_s_ = dt_s;
  if (spec_.has(OverlayKind::BackStep))
    for (const RigidBody& b : world.bodies) outlines_.push_back(bodyOutline(b));
  if (spec_.has(OverlayKind::EnergyInset))
    for (const FrameRecord& r : records_) {
      energy_.time.push_back(r.time);
      energy_.kinetic.push_back(r.kinetic);
      energy_.potential.push_back(r.potential);
    }
}

void OverlayRender::addMarks(DrawFrame& frame, int frame_number, const Trajectory& trajectory, int frame_height) const {
  frame.marks = DrawMarks{};
  if (!any() || !world_) return;
  static const FrameRecord kNone;   // from a trajectory file: velocities only, no record
  const std::size_t k = static_cast<std::size_t>(frame_number - 1);
  const FrameRecord& record = k < records_.size() ? records_[k] : kNone;
  frame.marks = overlayMarks(spec_, scales_, record, trajectory.frames[k], velocity_bodies_, *world_,
                             frame.camera.eye, frame_height);
  if (spec_.has(OverlayKind::BroadPhase)) addBroadPhaseMarks(record.broad_phase, frame.marks);
  if (spec_.has(OverlayKind::BackStep)) addBackStepMarks(record, outlines_, frame.marks);
}

void OverlayRender::addText(RgbImage& image, int frame_number, int frames, const DrawCamera& camera) const {
  const std::size_t k = static_cast<std::size_t>(frame_number - 1);
  if (spec_.has(OverlayKind::BackStep) && k < records_.size() && !records_[k].back_steps.empty()) {
    // Each back-step's count of trials beside its impact, placed as the marks are projected.
    const Eigen::Matrix4f view_proj =
        render::cameraViewProjection(camera, static_cast<float>(image.width) / static_cast<float>(image.height));
    const double font_px = overlayFontPx(image.height);
    for (const BackStepLabel& label : backStepLabels(records_[k])) {
      const Eigen::Vector4f clip = view_proj * label.at.cast<float>().homogeneous();
      if (clip.w() <= 0) continue;   // behind the camera
      const double x = (clip.x() / clip.w() * 0.5 + 0.5) * image.width;
      const double y = (0.5 - clip.y() / clip.w() * 0.5) * image.height;   // rows top first
      const OverlayPanel p = labelPanel(label.text, font_px, x, y);
      compositeOver(image, p.layer, p.x, p.y);
    }
  }
  if (spec_.has(OverlayKind::EnergyInset) && !energy_.time.empty()) {
    const OverlayPanel inset = energyInsetPanel(energy_, std::min(k + 1, energy_.time.size()), image.width, image.height);
    compositeOver(image, inset.layer, inset.x, inset.y);
  }
  if (spec_.has(OverlayKind::Hud) && !records_.empty()) {
    const FrameRecord& r = records_[static_cast<std::size_t>(frame_number - 1)];
    HudFigures h;
    h.time_s = r.time;
    h.frame = frame_number;
    h.frames = frames;
    h.model = model_;
    h.dt_s = dt_s_;
    h.kinetic = r.kinetic;
    h.potential = r.potential;
    h.start_total = records_.front().total();
    h.contacts = static_cast<int>(r.contacts.size());
    h.deepest_m = r.deepest_m;
    const OverlayPanel hud = hudPanel(h, image.height);
    compositeOver(image, hud.layer, hud.x, hud.y);
  }
  if (const std::optional<OverlayPanel> legend = legendPanel(spec_, scales_, image.height))
    compositeOver(image, legend->layer, legend->x, legend->y);
}

void OverlayRender::checkOutputs(const OutputTarget& target, bool overwrite) {
  if (!spec_.has(OverlayKind::EnergyPlot)) return;
  plot_png_ = energyPlotPath(target, scene_name_);
  checkEnergyPlotOutputs(plot_png_, overwrite);
}

void OverlayRender::writePlots(const Trajectory& trajectory, bool overwrite, bool quiet) const {
  if (plot_png_.empty() || records_.empty()) return;
  plot::EnergySeries series;
  series.title = scene_name_ + ": energy (" + model_ + ")";
  for (std::size_t k = 0; k < records_.size() && k < trajectory.times.size(); ++k) {
    series.time.push_back(trajectory.times[k]);
    series.kinetic.push_back(records_[k].kinetic);
    series.potential.push_back(records_[k].potential);
  }
  writeEnergyPlot(plot_png_, series, overwrite);
  if (!quiet)
    std::fprintf(stderr, "tumble: energy plot: %s (and .svg)\n", plot_png_.string().c_str());
}

}  // namespace tumble
