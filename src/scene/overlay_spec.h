// What is drawn over the frames: the scene's "overlays" and "overlay_bodies", and render
// --overlay. Pure data and the names of the kinds; no drawing here (src/render/overlay_*.cpp).
#pragma once

#include <string>
#include <vector>

namespace tumble {

enum class OverlayKind { Contacts, Forces, Velocities, Hud, EnergyPlot, BackStep, BroadPhase, EnergyInset };

struct OverlaySpec {
  std::vector<OverlayKind> kinds;      // in the order first asked for, each once
  std::vector<std::string> bodies;     // "overlay_bodies": velocities of these; empty: every moving body
  bool has(OverlayKind k) const;
  void add(OverlayKind k);             // keeps each kind once
  bool any() const { return !kinds.empty(); }
};

// "contacts", "forces", "velocities", "hud", "energy_plot", "back_step", "broad_phase",
// "energy_inset", in that order (the enum's).
const std::vector<std::string>& overlayNames();
const std::string& overlayName(OverlayKind k);
// The kind of a name, or false when the name is none of overlayNames().
bool parseOverlayKind(const std::string& name, OverlayKind& out);
// "unknown overlay \"contcts\"; did you mean \"contacts\"?" or "...; the overlays are contacts, ...".
std::string unknownOverlayMessage(const std::string& name);

}  // namespace tumble
