#include "app/overlay_options.h"

#include "base/error.h"

namespace tumble {

void addOverlayOption(CLI::App& command, std::vector<std::string>& names) {
  std::string kinds;
  for (const std::string& n : overlayNames()) kinds += (kinds.empty() ? "" : ", ") + n;
  command.add_option("--overlay", names,
                     "Draw over the frames: " + kinds + " (comma-separated, repeatable; all: every one); "
                     "adds to the scene's \"overlays\"")
      ->delimiter(',')
      ->type_name("NAMES");
}

OverlaySpec resolveOverlays(const OverlaySpec& scene, const std::vector<std::string>& names) {
  OverlaySpec out = scene;
  for (const std::string& name : names) {
    OverlayKind kind;
    if (name == "all") {
      for (std::size_t k = 0; k < overlayNames().size(); ++k) out.add(static_cast<OverlayKind>(k));
    } else if (parseOverlayKind(name, kind)) {
      out.add(kind);
    } else {
      throw Error(ExitCode::Usage, "--overlay: " + unknownOverlayMessage(name) + (name.empty() ? "" : " (or all)"));
    }
  }
  return out;
}

}  // namespace tumble
