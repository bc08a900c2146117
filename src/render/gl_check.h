// Turns GL's silent error flags into tumble::Error, so a broken setup fails loudly and early.
#pragma once

#include <string>

#include "render/gl_api.h"

namespace tumble::render {

// Throws Error(Unavailable) naming `what` if GL has recorded an error since the last check.
void throwIfGlError(const std::string& what);

// Throws Error(Unavailable) if the bound draw framebuffer is not complete.
void throwIfFramebufferIncomplete(const std::string& what);

}  // namespace tumble::render
