#pragma once
// The one seam between lpvlab and the platform's GL: a context backend that makes a GL 4.5 core
// context current (no window, no display) and loads every GL entry point through its own
// GetProcAddress into glad. The pipeline never knows which backend it runs on.
//   "osmesa": Mesa's llvmpipe on the CPU (always available; what tests and CI use).
//   "egl":    EGL with a surfaceless/pbuffer context, on a GPU device when there is one (NVIDIA),
//             else on whatever EGL offers (Mesa's EGL gives llvmpipe through a software device).
//   "auto":   egl on a GPU device if it yields a 4.5 context with the required extensions, else
//             osmesa (llvmpipe through EGL is no better than osmesa, which is the tested path).
//   "none":   no GL at all (gl.backend = "none"): nothing is loaded; GL buffers and textures live
//             on the host (resources.h), and whatever needs GL itself (a program, a draw, a
//             GL-only strategy) throws an Error saying so. For runs whose every stage runs on the
//             CPU, on machines without Mesa or a GPU.
//
// One context per process: glad's entry points are process-wide, so a second live context would
// silently redirect every GL call of the first. create() refuses while another context lives.

#include <memory>
#include <string>
#include <vector>

namespace lpvlab {

// What renderer() says without GL.
inline constexpr const char* kNoGlRenderer = "none (no GL)";

class GlContext {
public:
  virtual ~GlContext();
  virtual std::string backend() const = 0;   // "osmesa", "egl" or "none"
  std::string renderer() const;               // GL_RENDERER ("none (no GL)" without GL)
  std::string version() const;                // GL_VERSION ("" without GL)
  // Whether GL's entry points are loaded and a context is current in this process (false
  // before any context and with "none").
  static bool glLoaded();
  // GL_RENDERER of the current context, "none (no GL)" without one (what renderer() says).
  static std::string currentRenderer();

  // Creates the context and makes it current on this thread; throws Error naming the backend
  // and what is missing (e.g. GL_ARB_gl_spirv) when the context cannot serve lpvlab.
  static std::unique_ptr<GlContext> create(const std::string& backend = "auto");
  static std::vector<std::string> backends();  // those compiled in

  // GL errors reported through the debug output (KHR_debug) since the last call, oldest first.
  // The driver calls the debug callback from inside its C code, which an exception must not
  // cross, so the callback logs and checkGl() (resources.h) throws with these messages.
  static std::vector<std::string> takeDebugMessages();

protected:
  GlContext();
};

}  // namespace lpvlab
