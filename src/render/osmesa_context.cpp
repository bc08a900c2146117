#include "render/osmesa_context.h"

// osmesa.h pulls in the legacy GL/gl.h; keep it in this one file so the rest of the renderer sees
// only the core-profile declarations of gl_api.h.
#include <GL/osmesa.h>

#include <string>

#include "base/error.h"

#if defined(TUMBLE_SANITIZED)
// LeakSanitizer (TUMBLE_SANITIZE builds): Mesa's OSMesa leaks a few hundred bytes per context
// that no API call frees. OSMesaDestroyContext (Mesa 22.3, src/gallium/frontends/osmesa/osmesa.c)
// frees the st context but never the osmesa_buffer that OSMesaMakeCurrent created for it, nor
// some of what st_api_create_context allocates. The destructor below does destroy every context;
// without this, every process that renders exits with LeakSanitizer's status 1 after succeeding
// (the render tests, and the CLI tests that check `tumble render`'s exit codes and signals).
// The pattern names the library, not the two entry points: the stacks LeakSanitizer records
// at malloc stop inside Mesa (built without frame pointers), so they often hold no function name.
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
#endif

namespace tumble::render {

namespace {

constexpr int kBufferSide = 1;  // pixels: the default framebuffer is never used

const char* kInstallHint =
    "; OpenGL off-screen rendering needs Mesa's OSMesa with llvmpipe "
    "(Debian/Ubuntu: apt-get install libosmesa6)";

OSMesaContext asContext(void* p) { return static_cast<OSMesaContext>(p); }

}  // namespace

OsmesaContext::OsmesaContext() : buffer_(4 * kBufferSide * kBufferSide, 0) {
  // No depth/stencil on the OSMesa buffer: our FBOs carry their own attachments.
  const int attribs[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,    0,
                         OSMESA_STENCIL_BITS,  0,
                         OSMESA_ACCUM_BITS,    0,
                         OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3,
                         0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) {
    throw Error(ExitCode::Unavailable,
                std::string("cannot create an OpenGL 3.3 core context with OSMesa") + kInstallHint);
  }
  context_ = ctx;
  if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide)) {
    OSMesaDestroyContext(ctx);
    context_ = nullptr;
    throw Error(ExitCode::Unavailable,
                std::string("cannot make the OSMesa context current") + kInstallHint);
  }
}

OsmesaContext::~OsmesaContext() {
  if (!context_) return;
  if (OSMesaGetCurrentContext() == asContext(context_)) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
  OSMesaDestroyContext(asContext(context_));
}

void OsmesaContext::makeCurrent() {
  if (OSMesaGetCurrentContext() == asContext(context_)) return;
  if (!OSMesaMakeCurrent(asContext(context_), buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide,
                         kBufferSide)) {
    throw Error(ExitCode::Unavailable, "cannot make the OSMesa context current");
  }
}

}  // namespace tumble::render
