// The one place the renderer includes OpenGL. libOSMesa exports the GL 3.3 core entry points
// directly (checked on Mesa 22.3.6: glBlitFramebuffer, glTexImage2DMultisample,
// glVertexAttribDivisor ... are all in its dynamic symbol table), so prototypes are enough and no
// loader is needed. GL 4.x-only functions (e.g. glCreateVertexArrays) are NOT exported: using one
// fails at link time, which is the early warning we want.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
