#include "framework/gl/shader_compiler.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <fstream>
#include <set>

#include "framework/core/install_layout.h"
#include "framework/gl/context.h"
#include "framework/gl/resources.h"
#include "framework/core/error.h"

namespace lpvlab {
namespace {

// A SPIR-V module made ahead of time: `root`/<path>.spv (lpvlab-compile-spirv's output).
std::vector<std::uint32_t> readSpirv(const std::filesystem::path& root, const std::string& path) {
  const std::filesystem::path file = root / (path + ".spv");
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throwAt(path, "no SPIR-V at " + file.string() + " (made at build time by lpvlab-compile-spirv)");
  const std::streamsize bytes = in.tellg();
  std::vector<std::uint32_t> spirv(std::size_t(std::max<std::streamsize>(bytes, 0)) / 4);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(spirv.data()), std::streamsize(spirv.size() * 4));
  constexpr std::uint32_t kSpirvMagic = 0x07230203;
  if (!in || bytes % 4 != 0 || spirv.size() < 5 || spirv[0] != kSpirvMagic)
    throwAt(path, file.string() + " is not a SPIR-V module");
  return spirv;
}

// The constant_id of every specialization constant in a SPIR-V module: the literal of each
// OpDecorate(target, SpecId, id).
std::set<std::uint32_t> specConstantIds(const std::vector<std::uint32_t>& spirv) {
  constexpr std::uint32_t kOpDecorate = 71, kDecorationSpecId = 1;
  std::set<std::uint32_t> ids;
  for (std::size_t at = 5; at < spirv.size();) {  // 5 words of header
    const std::uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
    if (words == 0) break;
    if (opcode == kOpDecorate && words >= 4 && at + 3 < spirv.size() &&
        spirv[at + 2] == kDecorationSpecId)
      ids.insert(spirv[at + 3]);
    at += words;
  }
  return ids;
}

std::string glShaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log.c_str();
}

std::string glProgramLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log.c_str();
}

}  // namespace

SpecConstant SpecConstant::i(std::uint32_t id, int value) {
  return {id, std::bit_cast<std::uint32_t>(value)};
}
SpecConstant SpecConstant::u(std::uint32_t id, std::uint32_t value) { return {id, value}; }
SpecConstant SpecConstant::f(std::uint32_t id, float value) {
  return {id, std::bit_cast<std::uint32_t>(value)};
}
SpecConstant SpecConstant::b(std::uint32_t id, bool value) { return {id, value ? 1u : 0u}; }

Program& Program::operator=(Program&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

void Program::use() const { glUseProgram(id_); }

ShaderCompiler::ShaderCompiler(std::filesystem::path root, SpirvSource source)
    : root_(std::move(root)), source_(source) {}

ShaderCompiler ShaderCompiler::precompiled(std::filesystem::path spirvRoot) {
  return ShaderCompiler(std::move(spirvRoot), &readSpirv);
}

GLenum shaderStageOf(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".comp") return GL_COMPUTE_SHADER;
  if (extension == ".vert") return GL_VERTEX_SHADER;
  if (extension == ".frag") return GL_FRAGMENT_SHADER;
  if (extension == ".geom") return GL_GEOMETRY_SHADER;
  if (extension == ".tesc") return GL_TESS_CONTROL_SHADER;
  if (extension == ".tese") return GL_TESS_EVALUATION_SHADER;
  throwAt(path, "unknown shader stage (extension must be .comp .vert .frag .geom .tesc .tese)");
}

ShaderCompiler::~ShaderCompiler() = default;

std::filesystem::path ShaderCompiler::defaultRoot() { return shaderDirectory(); }

std::vector<std::uint32_t> ShaderCompiler::compileToSpirv(const std::string& path) {
  if (auto cached = cache_.find(path); cached != cache_.end()) return cached->second;
  shaderStageOf(path);  // an unknown stage is an error before anything is read
  return cache_[path] = source_(root_, path);
}

Program ShaderCompiler::link(const std::vector<std::string>& paths,
                             const std::vector<SpecConstant>& spec) {
  if (!GlContext::glLoaded()) gl::noGl("the GL program " + paths.back());
  std::string files;
  for (const std::string& path : paths) files += (files.empty() ? "" : " + ") + path;

  Program program(glCreateProgram());
  // Deleting an attached shader only flags it: GL frees it together with the program.
  struct Shaders {
    std::vector<GLuint> ids;
    ~Shaders() {
      for (GLuint id : ids) glDeleteShader(id);
    }
  } shaders;
  std::set<std::uint32_t> specialized;
  for (const std::string& path : paths) {
    const std::vector<std::uint32_t> spirv = compileToSpirv(path);
    // GL rejects a constant_id the module lacks, and a vertex and a fragment shader of one
    // program usually have different ones: each stage gets those it declares.
    const std::set<std::uint32_t> declared = specConstantIds(spirv);
    std::vector<GLuint> ids, values;
    for (const SpecConstant& constant : spec) {
      if (!declared.count(constant.id)) continue;
      ids.push_back(constant.id);
      values.push_back(constant.bits);
      specialized.insert(constant.id);
    }
    const GLuint shader = glCreateShader(shaderStageOf(path));
    shaders.ids.push_back(shader);
    glShaderBinary(1, &shader, GL_SHADER_BINARY_FORMAT_SPIR_V_ARB, spirv.data(),
                   GLsizei(spirv.size() * sizeof(std::uint32_t)));
    glSpecializeShaderARB(shader, "main", GLuint(ids.size()), ids.data(), values.data());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) throwAt(path, "GL rejects the SPIR-V: " + glShaderLog(shader));
    glAttachShader(program.id(), shader);
  }
  // A constant that no stage declares is a typo or a stale id, which GL would ignore silently.
  for (const SpecConstant& constant : spec)
    if (!specialized.count(constant.id))
      throwAt(files, "no specialization constant has constant_id = " +
                         std::to_string(constant.id));
  glLinkProgram(program.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) throwAt(files, "GL does not link the program: " + glProgramLog(program.id()));
  return program;
}

Program ShaderCompiler::compute(const std::string& path, const std::vector<SpecConstant>& spec) {
  return link({path}, spec);
}

Program ShaderCompiler::graphics(const std::string& vertexPath, const std::string& fragmentPath,
                                 const std::vector<SpecConstant>& spec) {
  return link({vertexPath, fragmentPath}, spec);
}

}  // namespace lpvlab
