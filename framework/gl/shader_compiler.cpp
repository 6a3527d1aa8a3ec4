#include "framework/gl/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <optional>
#include <set>
#include <sstream>

#include "framework/core/install_layout.h"
#include "framework/core/error.h"
#include "framework/gl/shader_includer.h"

namespace lpvlab {
namespace {

// glslang keeps process-wide tables; a function-local static initialises them exactly once, even
// when compilers on several threads start at the same time. They are never finalised: they are
// needed until the process ends, which frees them.
void initGlslang() {
  static const bool initialised = glslang::InitializeProcess();
  (void)initialised;
}

struct Stage {
  EShLanguage glslang;
  GLenum gl;
};

Stage stageOf(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".comp") return {EShLangCompute, GL_COMPUTE_SHADER};
  if (extension == ".vert") return {EShLangVertex, GL_VERTEX_SHADER};
  if (extension == ".frag") return {EShLangFragment, GL_FRAGMENT_SHADER};
  if (extension == ".geom") return {EShLangGeometry, GL_GEOMETRY_SHADER};
  if (extension == ".tesc") return {EShLangTessControl, GL_TESS_CONTROL_SHADER};
  if (extension == ".tese") return {EShLangTessEvaluation, GL_TESS_EVALUATION_SHADER};
  throwAt(path, "unknown shader stage (extension must be .comp .vert .frag .geom .tesc .tese)");
}

// glslang's log, one problem a line as "<file>:<line>: <message>". Its lines read
// "ERROR: common/sh.glsl:12: 'x' : undeclared identifier", with the file named as the includer
// named it (root-relative). Its summaries ("1 compilation errors. No code generated.", "'' :
// compilation terminated") say nothing more and are dropped.
std::string rewriteLog(const std::string& log) {
  std::istringstream lines(log);
  std::string line, out;
  while (std::getline(lines, line)) {
    if (line.rfind("ERROR: ", 0) == 0) {
      line.erase(0, 7);
    } else if (line.rfind("WARNING: ", 0) == 0) {
      line = "warning: " + line.substr(9);
    }
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line.empty() || line.find("compilation errors.") != std::string::npos ||
        line.find("compilation terminated") != std::string::npos)
      continue;
    out += "\n  " + line;
  }
  return out;
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

ShaderCompiler::ShaderCompiler(std::filesystem::path root) : root_(std::move(root)) {
  initGlslang();
}

ShaderCompiler::~ShaderCompiler() = default;

std::filesystem::path ShaderCompiler::defaultRoot() { return shaderDirectory(); }

std::vector<std::uint32_t> ShaderCompiler::compileToSpirv(const std::string& path) {
  if (auto cached = cache_.find(path); cached != cache_.end()) return cached->second;

  const Stage stage = stageOf(path);
  const std::optional<std::string> source = readTextFile(root_ / path);
  if (!source) throwAt(path, "shader file not found in " + root_.string());

  glslang::TShader shader(stage.glslang);
  const char* text = source->c_str();
  const int length = int(source->size());
  const char* name = path.c_str();  // what glslang calls the file in its messages
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  // The preamble comes after the shader's #version as far as glslang is concerned, so shaders
  // need not ask for #include support themselves.
  shader.setPreamble("#extension GL_GOOGLE_include_directive : require\n");
  shader.setEnvInput(glslang::EShSourceGlsl, stage.glslang, glslang::EShClientOpenGL, 450);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = EShMessages(EShMsgSpvRules);
  ShaderIncluder includer(root_);
  if (!shader.parse(GetDefaultResources(), 450, false, messages, includer))
    throwAt(path, "does not compile:" + rewriteLog(shader.getInfoLog()));

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages))
    throwAt(path, "does not link:" + rewriteLog(program.getInfoLog()));

  std::vector<std::uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(stage.glslang), spirv, &logger);
  if (spirv.empty()) throwAt(path, "no SPIR-V generated: " + logger.getAllMessages());
  return cache_[path] = std::move(spirv);
}

Program ShaderCompiler::link(const std::vector<std::string>& paths,
                             const std::vector<SpecConstant>& spec) {
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
    const GLuint shader = glCreateShader(stageOf(path).gl);
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
