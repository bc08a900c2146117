// Golden frames of each overlay kind at 160x120, in tests/golden/overlay_*/, re-made by
// tools/update-golden (the same scenes, frames and flags as here), compared at the golden tolerance
// (tests/app/test_golden.cpp says how it was measured).
#include <catch2/catch.hpp>

#include <filesystem>

#include "run_tumble.h"

using tumble::test::freshTempDir;
using tumble::test::runTumble;

namespace {

const std::string kSource = TUMBLE_SOURCE_DIR;
const std::string kTolerance = " --threshold 8 --max-fail 0.005";

struct OverlayGolden {
  const char* folder;    // under tests/golden/
  const char* scene;     // under the source tree
  const char* frames;
  const char* overlay;
  const char* extra = "";   // more flags: a demo's own overlays turned off, to show the one kind
};

// The list tools/update-golden renders.
const OverlayGolden kGoldens[] = {
    {"overlay_contacts", "scenes/knockdown.json", "10,40", "contacts"},
    {"overlay_forces", "scenes/knockdown.json", "10,40", "forces"},
    {"overlay_velocities", "scenes/knockdown.json", "10,22", "velocities"},
    {"overlay_hud", "scenes/knockdown.json", "22", "hud"},
    {"overlay_back_step", "scenes/demos/back_stepping.json", "7,42", "back_step", " --set 'overlays=[]'"},
    {"overlay_broad_phase", "scenes/knockdown.json", "10,40", "broad_phase"},
    {"overlay_energy_inset", "scenes/knockdown.json", "22,40", "energy_inset"},
};

}  // namespace

TEST_CASE("each overlay kind matches its golden frames", "[golden][overlays]") {
  const std::filesystem::path dir = freshTempDir("tumble_overlay_golden");
  for (const OverlayGolden& g : kGoldens) {
    INFO(g.folder);
    auto r = runTumble("render " + kSource + "/" + g.scene + " --size 160x120 --samples 4 --frames " + g.frames +
                       " --overlay " + g.overlay + g.extra + " -y -o " + (dir / g.folder).string() + "/ --check-against " +
                       kSource + "/tests/golden/" + g.folder + kTolerance);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("0 failed"));
  }
}

TEST_CASE("an overlay's golden comparison fails without the overlay", "[golden][overlays]") {
  const std::filesystem::path dir = freshTempDir("tumble_overlay_golden_missing");
  auto r = runTumble("render " + kSource + "/scenes/knockdown.json --size 160x120 --samples 4 --frames 10,40 -q -y -o " +
                     (dir / "f").string() + "/ --check-against " + kSource + "/tests/golden/overlay_contacts" + kTolerance);
  CHECK(r.exit_code == 1);
}
