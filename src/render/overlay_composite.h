// Lays a transparent layer (the overlays' text, drawn by cairo: plot/canvas.h, Target::Layer) over
// a read-back frame.
#pragma once

#include "base/image.h"

namespace tumble {

// out = layer + (1 - alpha) frame per channel, the layer's colour premultiplied by its alpha, with
// exact integer rounding (the same inputs give the same bytes). Throws Error(Software) when the
// sizes differ.
void compositeOver(RgbImage& frame, const RgbaImage& layer);

}  // namespace tumble
