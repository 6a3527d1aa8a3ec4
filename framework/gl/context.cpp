// Backend selection, GL loading and the checks that every backend's context must pass.

#include "framework/gl/context.h"

#include <glad/gl.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <mutex>
#include <utility>

#include "framework/core/error.h"
#include "framework/gl/context_backends.h"

namespace lpvlab {
namespace {

// Guards the one-context-per-process rule (see context.h).
std::mutex liveMutex;
bool contextLive = false;
std::atomic<bool> loaded = false;  // GL's entry points loaded for the live context (not "none")

// gl.backend = "none": a context without GL.
class NoGlContext final : public GlContext {
public:
  std::string backend() const override { return "none"; }
};

std::mutex debugMutex;
std::vector<std::string> debugMessages;
// A loop that fails every iteration must not grow the log without bound; the first messages
// are the ones that explain the failure.
constexpr std::size_t kMaxDebugMessages = 64;

void GLAD_API_PTR onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei length,
                                 const GLchar* message, const void*) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  std::lock_guard lock(debugMutex);
  if (debugMessages.size() < kMaxDebugMessages)
    debugMessages.emplace_back(message, length >= 0 ? std::size_t(length) : std::strlen(message));
}

std::string glString(GLenum name) {
  const GLubyte* value = glGetString(name);
  return value ? reinterpret_cast<const char*>(value) : "";
}

// Loads GL through the backend, checks what lpvlab needs, and routes GL errors into the log.
std::unique_ptr<GlContext> finish(gl_detail::CurrentContext current) {
  const std::string backend = current.context->backend();
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(current.load)))
    throwAt(backend, "could not load GL entry points");

  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const int version = major * 10 + minor;
  std::vector<std::string> missing;
  if (version < 45) missing.push_back("GL 4.5");
  if (!GLAD_GL_ARB_gl_spirv) {
    // GL 4.6 has SPIR-V in core under the extension's name minus the suffix; the loader is
    // generated for 4.5, so the core entry point is fetched by hand under the ARB name.
    if (version >= 46)
      glad_glSpecializeShaderARB =
          reinterpret_cast<PFNGLSPECIALIZESHADERARBPROC>(current.load("glSpecializeShader"));
    if (version < 46 || !glad_glSpecializeShaderARB)
      missing.push_back("GL_ARB_gl_spirv (or GL 4.6)");
  }
  if (!GLAD_GL_NV_shader_atomic_float) missing.push_back("GL_NV_shader_atomic_float");
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    throwAt(backend, glString(GL_RENDERER) + " (GL " + glString(GL_VERSION) + ") lacks " + list);
  }

  {
    std::lock_guard lock(debugMutex);
    debugMessages.clear();
  }
  glEnable(GL_DEBUG_OUTPUT);
  // Synchronous, so that a message arrives inside the call that caused it and checkGl() right
  // after that call reports it.
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  loaded = true;
  return std::move(current.context);
}

}  // namespace

GlContext::GlContext() {
  std::lock_guard lock(liveMutex);
  contextLive = true;
}

GlContext::~GlContext() {
  std::lock_guard lock(liveMutex);
  contextLive = false;
  loaded = false;
}

bool GlContext::glLoaded() { return loaded; }

std::string GlContext::currentRenderer() { return glLoaded() ? glString(GL_RENDERER) : kNoGlRenderer; }
std::string GlContext::renderer() const { return currentRenderer(); }
std::string GlContext::version() const { return glLoaded() ? glString(GL_VERSION) : ""; }

std::vector<std::string> GlContext::backends() {
#if LPVLAB_HAVE_EGL
  return {"osmesa", "egl"};
#else
  return {"osmesa"};
#endif
}

std::unique_ptr<GlContext> GlContext::create(const std::string& backend) {
  const std::vector<std::string> compiled = backends();
  if (backend != "auto" && backend != "none" &&
      std::find(compiled.begin(), compiled.end(), backend) == compiled.end()) {
    std::string valid = "auto, none";
    for (const std::string& name : compiled) valid += ", " + name;
    throwAt("GL context", "unknown backend '" + backend + "' (valid: " + valid + ")");
  }
  {
    std::lock_guard lock(liveMutex);
    if (contextLive)
      throwAt("GL context", "one already exists in this process (lpvlab uses one per process)");
  }
  if (backend == "none") return std::make_unique<NoGlContext>();
  if (backend == "osmesa") return finish(gl_detail::createOsMesaContext());
#if LPVLAB_HAVE_EGL
  if (backend == "egl") return finish(gl_detail::createEglContext(false));
  // "auto": a GPU through EGL; else Mesa's software renderer through EGL (surfaceless: OSMesa is
  // gone from Mesa since 25.1); else OSMesa where it is still installed. The failures matter only
  // if the last fails too.
  std::string failures;
  for (const auto& create : {+[] { return gl_detail::createEglContext(true); },
                             +[] { return gl_detail::createEglContext(false); }}) {
    try {
      return finish(create());
    } catch (const Error& e) {
      failures += std::string(failures.empty() ? "" : "; ") + e.what();
    }
  }
  try {
    return finish(gl_detail::createOsMesaContext());
  } catch (const Error& e) {
    throw Error(std::string(e.what()) + "; and before that, " + failures);
  }
#else
  return finish(gl_detail::createOsMesaContext());
#endif
}

std::vector<std::string> GlContext::takeDebugMessages() {
  std::lock_guard lock(debugMutex);
  return std::exchange(debugMessages, {});
}

}  // namespace lpvlab
