// The "osmesa" backend: Mesa's off-screen GL on llvmpipe, needing no display and no GPU.

#include <GL/osmesa.h>

#include <array>

#include "framework/core/error.h"
#include "framework/gl/context_backends.h"

namespace lpvlab::gl_detail {
namespace {

class OsMesaContext : public GlContext {
public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throwAt("osmesa", "OSMesaCreateContextAttribs gave no GL 4.5 core context");
    // OSMesa binds a context only together with a colour buffer; lpvlab renders into its own
    // framebuffer objects, so a single pixel is enough.
    if (!OSMesaMakeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(context_);
      throwAt("osmesa", "OSMesaMakeCurrent failed");
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }
  std::string backend() const override { return "osmesa"; }

private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
};

}  // namespace

CurrentContext createOsMesaContext() {
  return {std::make_unique<OsMesaContext>(), &OSMesaGetProcAddress};
}

}  // namespace lpvlab::gl_detail
