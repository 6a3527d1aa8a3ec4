// GLSL -> SPIR-V by glslang, the default source of ShaderCompiler's SPIR-V. In a translation unit
// of its own so that a program that only loads SPIR-V made ahead of time
// (ShaderCompiler::precompiled, lpvlab-gpubench) links neither glslang nor SPIRV-Tools.

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/shader_compiler.h"
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

// glslang's stage for a file of the stage shaderStageOf names.
EShLanguage glslangStageOf(const std::string& path) {
  switch (shaderStageOf(path)) {
    case GL_VERTEX_SHADER: return EShLangVertex;
    case GL_FRAGMENT_SHADER: return EShLangFragment;
    case GL_GEOMETRY_SHADER: return EShLangGeometry;
    case GL_TESS_CONTROL_SHADER: return EShLangTessControl;
    case GL_TESS_EVALUATION_SHADER: return EShLangTessEvaluation;
    default: return EShLangCompute;
  }
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

// `root`/`path` compiled for GL 4.5 through GL_ARB_gl_spirv; includes resolved by ShaderIncluder.
std::vector<std::uint32_t> glslToSpirv(const std::filesystem::path& root, const std::string& path) {
  const EShLanguage stage = glslangStageOf(path);
  const std::optional<std::string> source = readTextFile(root / path);
  if (!source) throwAt(path, "shader file not found in " + root.string());

  glslang::TShader shader(stage);
  const char* text = source->c_str();
  const int length = int(source->size());
  const char* name = path.c_str();  // what glslang calls the file in its messages
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  // The preamble comes after the shader's #version as far as glslang is concerned, so shaders
  // need not ask for #include support themselves.
  shader.setPreamble("#extension GL_GOOGLE_include_directive : require\n");
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientOpenGL, 450);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = EShMessages(EShMsgSpvRules);
  ShaderIncluder includer(root);
  if (!shader.parse(GetDefaultResources(), 450, false, messages, includer))
    throwAt(path, "does not compile:" + rewriteLog(shader.getInfoLog()));

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages))
    throwAt(path, "does not link:" + rewriteLog(program.getInfoLog()));

  std::vector<std::uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger);
  if (spirv.empty()) throwAt(path, "no SPIR-V generated: " + logger.getAllMessages());
  return spirv;
}

}  // namespace

ShaderCompiler::ShaderCompiler(std::filesystem::path root)
    : ShaderCompiler(std::move(root), &glslToSpirv) {
  initGlslang();
}

}  // namespace lpvlab
