// The provenance a render stamps on its outputs: this build, and a hash of the scene as it was
// resolved — the JSON after --set and --patch, and the settings after the other flags — so two
// frames that differ can tell whether they came from different scenes.
#pragma once

#include <string>

#include "io/provenance.h"
#include "scene/scene.h"

namespace tumble {

// `camera`: the --camera picked ("" for the scene's default). The renderer is left empty: it is
// known once the renderer exists.
Provenance frameProvenance(const Scene& scene, const std::string& camera);

}  // namespace tumble
