// Lays a transparent layer (the overlays' text, drawn by cairo: plot/canvas.h, Target::Layer) over
// a read-back frame.
#pragma once

#include "base/image.h"

namespace tumble {

// out = layer + (1 - alpha) frame per channel, the layer's colour premultiplied by its alpha, with
// exact integer rounding (the same inputs give the same bytes). The layer's top-left corner goes at
// (x, y) in the frame; what falls outside the frame is left out.
void compositeOver(RgbImage& frame, const RgbaImage& layer, int x = 0, int y = 0);

}  // namespace tumble
