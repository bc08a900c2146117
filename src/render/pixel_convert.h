// From what GL reads back to what the rest of tumble wants. GL-free so it can be tested alone.
#pragma once

#include <cstdint>
#include <vector>

#include "base/image.h"

namespace tumble::render {

// RGBA rows bottom-up (glReadPixels) -> tightly packed RGB rows top-down (RgbImage).
void rgbaBottomUpToRgbTopDown(const std::vector<std::uint8_t>& rgba, int width, int height,
                              RgbImage& out);

// Linear -> sRGB transfer (IEC 61966-2-1), the same formula as encodeSrgb in lighting.glsl,
// used for the clear colour so the background matches faded ground pixels.
float encodeSrgb(float linear);

}  // namespace tumble::render
