// The "egl" backend: a GL 4.5 core context without any surface to draw on (surfaceless, or a
// 1x1 pbuffer where EGL_KHR_surfaceless_context is missing), on an EGL device chosen through
// EGL_EXT_platform_device so that no X server or Wayland compositor is needed. libEGL (glvnd's,
// which finds the GPU vendor's driver) is opened at run time (shared_library.h): it comes from
// the system lpvlab runs on, and a machine without it still runs OSMesa.

#if LPVLAB_HAVE_EGL

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/context_backends.h"
#include "framework/gl/shared_library.h"

namespace lpvlab::gl_detail {
namespace {

// EGL's core entry points lpvlab calls (extensions come through getProcAddress), from libEGL
// opened once per process.
struct EglApi {
  SharedLibrary library{"egl", {"libEGL.so.1", "libEGL.so"},
                        "install the system's EGL (Debian: libegl1, and the GPU's driver)"};
  template <class F>
  F load(const char* name) const { return library.function<F>(name); }
#define LPVLAB_EGL(name) decltype(&::name) name = load<decltype(&::name)>(#name)
  LPVLAB_EGL(eglGetProcAddress);
  LPVLAB_EGL(eglQueryString);
  LPVLAB_EGL(eglGetError);
  LPVLAB_EGL(eglGetDisplay);
  LPVLAB_EGL(eglInitialize);
  LPVLAB_EGL(eglTerminate);
  LPVLAB_EGL(eglBindAPI);
  LPVLAB_EGL(eglChooseConfig);
  LPVLAB_EGL(eglCreateContext);
  LPVLAB_EGL(eglDestroyContext);
  LPVLAB_EGL(eglCreatePbufferSurface);
  LPVLAB_EGL(eglDestroySurface);
  LPVLAB_EGL(eglMakeCurrent);
#undef LPVLAB_EGL
};

const EglApi& egl() {
  static const EglApi api;  // a failed load throws, and the next call tries again
  return api;
}

// eglGetProcAddress through the loaded library, as a plain function for glad.
GlProc getProcAddress(const char* name) {
  return reinterpret_cast<GlProc>(egl().eglGetProcAddress(name));
}

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string padded = " " + std::string(list) + " ";
  return padded.find(" " + name + " ") != std::string::npos;
}

// Throws with EGL's error code of the last call appended: EGL reports why in nothing else.
[[noreturn]] void fail(const std::string& what) {
  char code[32];
  std::snprintf(code, sizeof code, " (EGL error 0x%04X)", static_cast<unsigned>(egl().eglGetError()));
  throwAt("egl", what + code);
}

// An initialised display, on a GPU device when the device extensions can find one (devices
// that fail to initialise, e.g. a GPU without a driver for this EGL, are passed over);
// EGL_MESA_device_software marks Mesa's CPU renderers. Without device enumeration, the default
// display is all there is.
EGLDisplay openDisplay(bool requireGpu) {
  std::vector<EGLDisplay> candidates;
  const char* client = egl().eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl().eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      egl().eglGetProcAddress("eglQueryDeviceStringEXT"));
  auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl().eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLint count = 0;
  if (hasExtension(client, "EGL_EXT_platform_device") && queryDevices && queryDeviceString &&
      platformDisplay && queryDevices(0, nullptr, &count) && count > 0) {
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    queryDevices(count, devices.data(), &count);
    std::vector<EGLDisplay> software;
    for (EGLDeviceEXT device : devices) {
      const bool isSoftware =
          hasExtension(queryDeviceString(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
      EGLDisplay display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      if (display != EGL_NO_DISPLAY) (isSoftware ? software : candidates).push_back(display);
    }
    if (!requireGpu) candidates.insert(candidates.end(), software.begin(), software.end());
  } else if (requireGpu) {
    throwAt("egl", "cannot tell GPU devices from others (no EGL_EXT_platform_device)");
  } else {
    candidates.push_back(egl().eglGetDisplay(EGL_DEFAULT_DISPLAY));
  }
  if (candidates.empty())
    throwAt("egl", requireGpu ? "no GPU device (EGL offers software renderers only)"
                              : "no EGL device");
  for (EGLDisplay display : candidates) {
    EGLint major = 0, minor = 0;
    if (display != EGL_NO_DISPLAY && egl().eglInitialize(display, &major, &minor)) return display;
  }
  fail("no EGL display could be initialised");
}

class EglContext : public GlContext {
public:
  explicit EglContext(bool requireGpu) {
    display_ = openDisplay(requireGpu);
    try {
      setUp();
    } catch (...) {
      release();
      throw;
    }
  }
  ~EglContext() override { release(); }
  std::string backend() const override { return "egl"; }

private:
  void setUp() {
    if (!egl().eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed: no desktop GL");
    const bool surfaceless =
        hasExtension(egl().eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                       EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                       EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                       EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!egl().eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs < 1)
      fail("no EGL config for desktop GL");
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                        EGL_CONTEXT_MINOR_VERSION, 5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    context_ = egl().eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
    if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext gave no GL 4.5 core context");
    if (!surfaceless) {
      const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface_ = egl().eglCreatePbufferSurface(display_, config, pbufferAttributes);
      if (surface_ == EGL_NO_SURFACE) fail("no surfaceless contexts and no pbuffer surface");
    }
    if (!egl().eglMakeCurrent(display_, surface_, surface_, context_)) fail("eglMakeCurrent failed");
  }

  void release() {
    if (display_ == EGL_NO_DISPLAY) return;
    egl().eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) egl().eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) egl().eglDestroyContext(display_, context_);
    egl().eglTerminate(display_);
    display_ = EGL_NO_DISPLAY;
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
};

}  // namespace

CurrentContext createEglContext(bool requireGpu) {
  return {std::make_unique<EglContext>(requireGpu), &getProcAddress};
}

}  // namespace lpvlab::gl_detail

#endif  // LPVLAB_HAVE_EGL
