#pragma once
// GLSL from shaders/ compiled at run time by glslang to SPIR-V (resolving #include relative to
// the including file, then to shaders/), and loaded through GL_ARB_gl_spirv. A variant's
// compile-time parameters are SPIR-V specialization constants. A compile or link error throws
// an Error that names the shader file and line.
// Shaders need not enable GL_GOOGLE_include_directive themselves. glslang 12 ignores
// `#pragma once`: shared includes need #ifndef guards. SPIR-V keeps no names, so uniforms need
// `layout(location = N)` and buffers, images and samplers `layout(binding = N)`.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glad/gl.h>

namespace lpvlab {

struct SpecConstant {
  std::uint32_t id = 0;      // layout(constant_id = id)
  std::uint32_t bits = 0;    // the value's 32 bits
  static SpecConstant i(std::uint32_t id, int value);
  static SpecConstant u(std::uint32_t id, std::uint32_t value);
  static SpecConstant f(std::uint32_t id, float value);
  static SpecConstant b(std::uint32_t id, bool value);
};

// An owned GL program object.
class Program {
public:
  Program() = default;
  explicit Program(GLuint id) : id_(id) {}
  Program(Program&& other) noexcept : id_(other.id_) { other.id_ = 0; }
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();
  GLuint id() const { return id_; }
  void use() const;

private:
  GLuint id_ = 0;
};

// The stage a shader file holds, by its extension (.comp .vert .frag .geom .tesc .tese): its GL
// shader type; any other extension is an Error naming the file.
GLenum shaderStageOf(const std::string& path);

class ShaderCompiler {
public:
  // `root` is the shaders/ folder (default: LPVLAB_SHADER_DIR env var, else the source tree's);
  // its GLSL is compiled by glslang at run time (shader_compiler_glsl.cpp).
  explicit ShaderCompiler(std::filesystem::path root = defaultRoot());
  // SPIR-V made ahead of time instead of GLSL: `spirvRoot`/<path>.spv for each path (the output
  // of lpvlab-compile-spirv). A program that only calls this links no glslang.
  static ShaderCompiler precompiled(std::filesystem::path spirvRoot);
  ShaderCompiler(ShaderCompiler&&) = default;
  ~ShaderCompiler();

  // `path` relative to root, e.g. "propagation/standard.comp". SPIR-V is cached per file for
  // the compiler's lifetime; specialization happens per call, and a constant that no stage
  // declares is an Error (GL would ignore it). Needs the GL context current.
  Program compute(const std::string& path, const std::vector<SpecConstant>& spec = {});
  Program graphics(const std::string& vertexPath, const std::string& fragmentPath,
                   const std::vector<SpecConstant>& spec = {});

  // The SPIR-V of `path` (GLSL compiled, or read where precompiled; no GL needed): for tests and
  // for checking shaders without a context.
  // Errors read "<path>: does not compile:" followed by one "<file>:<line>: <message>" line per
  // problem, <file> relative to the root (an included file names itself, not its includer).
  std::vector<std::uint32_t> compileToSpirv(const std::string& path);

  static std::filesystem::path defaultRoot();

private:
  using SpirvSource = std::vector<std::uint32_t> (*)(const std::filesystem::path& root,
                                                     const std::string& path);
  ShaderCompiler(std::filesystem::path root, SpirvSource source);
  // One program from the stages in `paths`; each stage is specialized with the constants it
  // declares, and a constant that no stage declares is an Error.
  Program link(const std::vector<std::string>& paths, const std::vector<SpecConstant>& spec);
  std::filesystem::path root_;
  SpirvSource source_;
  std::map<std::string, std::vector<std::uint32_t>> cache_;
};

}  // namespace lpvlab
