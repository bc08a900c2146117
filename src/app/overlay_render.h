// The overlays of one render (README, "Overlays"): records what they need while the simulation
// runs (dynamics/frame_record.h), then per frame adds the marks to the draw list and lays the text
// (and the energy inset) over the read-back image, and at the end writes the energy plot. Render
// asks it at each point; with no overlays it does nothing.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/overlay_marks.h"
#include "app/piece_outline.h"
#include "app/scene_drawing.h"
#include "base/image.h"
#include "dynamics/frame_record.h"
#include "dynamics/simulator.h"
#include "io/output_path.h"
#include "plot/energy_plot.h"
#include "scene/scene.h"

namespace tumble {

class OverlayRender {
 public:
  OverlayRender(const Scene& scene, OverlaySpec spec);
  bool any() const { return spec_.any(); }
  // Whether the overlays need the simulation's records (all but velocities do): a render from a
  // trajectory file has only the motion, and refuses them (Error(Usage), 64).
  void checkMotionSource(bool from_trajectory) const;
  // Before the run: the recorder, the impact log and, for back_step, the back-step log.
  void attach(Simulator& simulator, const StepSettings& settings);
  // After each simulated frame, the first included (Simulator::run's on_frame).
  void onFrame(const Simulator& simulator);
  // After the run: the clip's scales. `world`: the bodies (masses, which are static).
  void prepare(const World& world, const SceneDrawing& drawing, const Trajectory& trajectory,
               const std::string& model, double dt_s);
  // Frame `frame` (from 1): its marks into the draw list, its text over the image.
  void addMarks(DrawFrame& frame, int frame_number, const Trajectory& trajectory, int frame_height) const;
  // `camera`: the frame's, to place labels by the points they name.
  void addText(RgbImage& image, int frame_number, int frames, const DrawCamera& camera) const;
  // The energy plot, when asked for: its path is checked before any work, written at the end.
  void checkOutputs(const OutputTarget& target, bool overwrite);
  void writePlots(const Trajectory& trajectory, bool overwrite, bool quiet) const;

 private:
  std::string scene_name_;
  OverlaySpec spec_;
  std::optional<FrameRecorder> recorder_;
  std::vector<ImpactMark> impacts_;       // since the last frame recorded
  BackStepLog back_steps_;                // likewise, the last few (back_step only)
  std::vector<FrameRecord> records_;      // per simulated frame
  const World* world_ = nullptr;
  OverlayScales scales_;
  std::vector<int> velocity_bodies_;
  std::vector<std::vector<OutlineSegment>> outlines_;   // per body, for back_step's ghosts
  plot::EnergySeries energy_;             // the clip's, for energy_inset
  std::string model_;
  double dt_s_ = 0;
  std::filesystem::path plot_png_;
};

}  // namespace tumble
