// The "osmesa" backend: Mesa's off-screen GL on llvmpipe, needing no display and no GPU.
// libOSMesa is opened at run time (shared_library.h): Mesa 25.1 dropped it upstream, and a GPU
// machine should not need it (nor the LLVM it pulls in).

#include <GL/osmesa.h>

#include <array>

#include "framework/core/error.h"
#include "framework/gl/context_backends.h"
#include "framework/gl/shared_library.h"

namespace lpvlab::gl_detail {
namespace {

// OSMesa's entry points lpvlab calls, from the library opened once per process.
struct OsMesaApi {
  SharedLibrary library{"osmesa", {"libOSMesa.so.8", "libOSMesa.so"},
                        "install Mesa's OSMesa (Debian: libosmesa6), or use gl.backend = \"egl\""};
  decltype(&OSMesaCreateContextAttribs) createContextAttribs =
      library.function<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
  decltype(&OSMesaMakeCurrent) makeCurrent =
      library.function<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
  decltype(&OSMesaDestroyContext) destroyContext =
      library.function<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
  decltype(&OSMesaGetProcAddress) getProcAddress =
      library.function<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress");
};

const OsMesaApi& osMesa() {
  static const OsMesaApi api;  // a failed load throws, and the next call tries again
  return api;
}

// OSMesaGetProcAddress through the loaded library, as a plain function for glad.
GlProc getProcAddress(const char* name) {
  return reinterpret_cast<GlProc>(osMesa().getProcAddress(name));
}

class OsMesaContext : public GlContext {
public:
  OsMesaContext() : api_(osMesa()) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    context_ = api_.createContextAttribs(attributes, nullptr);
    if (!context_) throwAt("osmesa", "OSMesaCreateContextAttribs gave no GL 4.5 core context");
    // OSMesa binds a context only together with a colour buffer; lpvlab renders into its own
    // framebuffer objects, so a single pixel is enough.
    if (!api_.makeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      api_.destroyContext(context_);
      throwAt("osmesa", "OSMesaMakeCurrent failed");
    }
  }
  ~OsMesaContext() override { api_.destroyContext(context_); }
  std::string backend() const override { return "osmesa"; }

private:
  const OsMesaApi& api_;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
};

}  // namespace

CurrentContext createOsMesaContext() {
  return {std::make_unique<OsMesaContext>(), &getProcAddress};
}

}  // namespace lpvlab::gl_detail
