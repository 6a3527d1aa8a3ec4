#pragma once
// Internal to framework/gl: what context.cpp needs from each backend. A backend makes its
// context current and hands back its GetProcAddress; context.cpp loads GL through it and checks
// that the context can serve lpvlab, the same way for every backend.

#include <memory>

#include "framework/gl/context.h"

namespace lpvlab::gl_detail {

// The signature of OSMesaGetProcAddress and eglGetProcAddress (and glad's GLADloadfunc), spelled
// out so that backends need not include glad next to their own GL headers.
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

struct CurrentContext {
  std::unique_ptr<GlContext> context;
  GlProcLoader load = nullptr;
};

// Each throws an Error beginning with the backend's name when it cannot make a context current.
CurrentContext createOsMesaContext();
#if LPVLAB_HAVE_EGL
// requireGpu: refuse EGL devices that are software renderers (what "auto" wants).
CurrentContext createEglContext(bool requireGpu);
#endif

}  // namespace lpvlab::gl_detail
