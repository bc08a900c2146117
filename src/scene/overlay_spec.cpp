#include "scene/overlay_spec.h"

#include <algorithm>

#include "scene/suggest.h"

namespace tumble {

bool OverlaySpec::has(OverlayKind k) const { return std::find(kinds.begin(), kinds.end(), k) != kinds.end(); }

void OverlaySpec::add(OverlayKind k) {
  if (!has(k)) kinds.push_back(k);
}

const std::vector<std::string>& overlayNames() {
  static const std::vector<std::string> names{"contacts", "forces",    "velocities",  "hud",
                                              "energy_plot", "back_step", "broad_phase", "energy_inset"};
  return names;
}

const std::string& overlayName(OverlayKind k) { return overlayNames()[static_cast<std::size_t>(k)]; }

bool parseOverlayKind(const std::string& name, OverlayKind& out) {
  const std::vector<std::string>& names = overlayNames();
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return false;
  out = static_cast<OverlayKind>(it - names.begin());
  return true;
}

std::string unknownOverlayMessage(const std::string& name) {
  std::string message = "unknown overlay \"" + name + "\"";
  const std::string near = closestMatch(name, overlayNames());
  if (!near.empty()) return message + "; did you mean \"" + near + "\"?";
  message += "; the overlays are";
  for (const std::string& n : overlayNames()) message += " " + n + (n == overlayNames().back() ? "" : ",");
  return message;
}

}  // namespace tumble
