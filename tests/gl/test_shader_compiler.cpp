#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>

#include "framework/core/error.h"
#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no Error)";
}

// A shader root in a temporary folder, removed afterwards.
class TempShaders : public testing::Test {
protected:
  void SetUp() override {
    const auto* test = testing::UnitTest::GetInstance()->current_test_info();
    root_ = std::filesystem::temp_directory_path() /
            ("lpvlab_gl_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }
  void write(const std::string& path, const std::string& text) {
    std::filesystem::create_directories((root_ / path).parent_path());
    std::ofstream(root_ / path) << text;
  }
  // a.comp includes common/b.glsl, which includes c.glsl next to it (common/c.glsl, not the
  // decoy c.glsl at the root) and util/d.glsl (at the root: there is no common/util/d.glsl).
  void writeIncludeChain(const std::string& cBody) {
    write("a.comp",
          "#version 450\n"
          "layout(local_size_x = 1) in;\n"
          "#include \"common/b.glsl\"\n"
          "layout(std430, binding = 0) buffer Out { float value; };\n"
          "void main() { value = fromB(); }\n");
    write("common/b.glsl",
          "#include \"c.glsl\"\n"
          "#include \"util/d.glsl\"\n"
          "float fromB() { return fromC() + fromD(); }\n");
    write("common/c.glsl", cBody);
    write("c.glsl", "float fromC() { return 1000.0; }\n");
    write("util/d.glsl", "float fromD() { return 0.5; }\n");
  }
  std::filesystem::path root_;
};

TEST(ShaderCompiler, SpecializationConstantsReachTheShader) {
  test::glTestContext();
  ShaderCompiler compiler(test::testShaderRoot());
  const Program program = compiler.compute(
      "spec_constants.comp",
      {SpecConstant::u(0, 48), SpecConstant::i(1, -7), SpecConstant::f(2, 2.5f)});
  GLint size[3] = {};
  glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  EXPECT_EQ(size[0], 48);

  struct Out {
    std::uint32_t localSize;
    std::int32_t intValue;
    float floatValue;
    std::uint32_t invocations;
  } out{};
  gl::Buffer buffer(sizeof out, "spec.out");
  buffer.bindStorage(0);
  program.use();
  glDispatchCompute(3, 1, 1);
  buffer.download(&out, sizeof out);
  checkGl("spec constants");
  EXPECT_EQ(out.localSize, 48u);
  EXPECT_EQ(out.intValue, -7);
  EXPECT_EQ(out.floatValue, 2.5f);
  EXPECT_EQ(out.invocations, 3u * 48);
}

TEST(ShaderCompiler, UnknownConstantIdIsAnError) {
  test::glTestContext();
  ShaderCompiler compiler(test::testShaderRoot());
  const std::string message =
      messageOf([&] { compiler.compute("spec_constants.comp", {SpecConstant::i(9, 1)}); });
  EXPECT_NE(message.find("spec_constants.comp: no specialization constant has constant_id = 9"),
            std::string::npos)
      << message;
}

TEST_F(TempShaders, IncludesResolveBesideTheIncluderThenAtTheRoot) {
  test::glTestContext();
  writeIncludeChain("float fromC() { return 2.0; }\n");
  ShaderCompiler compiler(root_);
  const Program program = compiler.compute("a.comp");
  gl::Buffer buffer(sizeof(float), "include.out");
  buffer.bindStorage(0);
  program.use();
  glDispatchCompute(1, 1, 1);
  float value = 0.0f;
  buffer.download(&value, sizeof value);
  EXPECT_EQ(value, 2.5f);  // common/c.glsl's 2 and util/d.glsl's 0.5
}

TEST_F(TempShaders, ErrorInAnIncludedFileNamesThatFileAndLine) {
  writeIncludeChain("// c.glsl\n"
                    "float fromC() {\n"
                    "  return 2.0;\n"
                    "  this is not glsl;\n"
                    "}\n");
  ShaderCompiler compiler(root_);
  const std::string message = messageOf([&] { compiler.compileToSpirv("a.comp"); });
  EXPECT_EQ(message.rfind("a.comp: does not compile:", 0), 0u) << message;
  EXPECT_NE(message.find("\n  common/c.glsl:4: "), std::string::npos) << message;
}

TEST_F(TempShaders, ErrorAfterAnIncludeKeepsTheIncludersLines) {
  writeIncludeChain("float fromC() { return 2.0; }\n");
  write("e.comp",
        "#version 450\n"
        "layout(local_size_x = 1) in;\n"
        "#include \"common/b.glsl\"\n"
        "void main() {\n"
        "  float x = undeclared;\n"
        "}\n");
  ShaderCompiler compiler(root_);
  const std::string message = messageOf([&] { compiler.compileToSpirv("e.comp"); });
  EXPECT_NE(message.find("\n  e.comp:5: 'undeclared' : undeclared identifier"), std::string::npos)
      << message;
}

TEST_F(TempShaders, MissingIncludeNamesTheFileAndTheIncluder) {
  writeIncludeChain("#include \"nowhere.glsl\"\n"
                    "float fromC() { return 2.0; }\n");
  ShaderCompiler compiler(root_);
  const std::string message = messageOf([&] { compiler.compileToSpirv("a.comp"); });
  EXPECT_NE(message.find("\n  common/c.glsl:1: '#include' : not found"), std::string::npos)
      << message;
  EXPECT_NE(message.find("nowhere.glsl"), std::string::npos) << message;
}

TEST_F(TempShaders, IncludeCycleIsAnErrorNotAHang) {
  write("cycle.comp",
        "#version 450\n"
        "layout(local_size_x = 1) in;\n"
        "#include \"loop/self.glsl\"\n"
        "void main() {}\n");
  write("loop/self.glsl", "#include \"self.glsl\"\n");
  ShaderCompiler compiler(root_);
  const std::string message = messageOf([&] { compiler.compileToSpirv("cycle.comp"); });
  EXPECT_NE(message.find("\n  loop/self.glsl:1: '#include' : nested more than"),
            std::string::npos)
      << message;
}

TEST_F(TempShaders, MissingShaderFileIsNamed) {
  ShaderCompiler compiler(root_);
  const std::string message = messageOf([&] { compiler.compileToSpirv("deep/nothing.comp"); });
  EXPECT_EQ(message.rfind("deep/nothing.comp: shader file not found in ", 0), 0u) << message;
}

TEST_F(TempShaders, SpirvIsCachedPerFile) {
  writeIncludeChain("float fromC() { return 2.0; }\n");
  ShaderCompiler compiler(root_);
  const std::vector<std::uint32_t> first = compiler.compileToSpirv("a.comp");
  ASSERT_GT(first.size(), 5u);
  EXPECT_EQ(first[0], 0x07230203u);  // the SPIR-V magic number
  std::filesystem::remove(root_ / "a.comp");
  EXPECT_EQ(compiler.compileToSpirv("a.comp"), first);
}

TEST(ShaderCompiler, GraphicsProgramDrawsIntoTwoTargets) {
  test::glTestContext();
  ShaderCompiler compiler(test::testShaderRoot());
  // kRed exists in the fragment shader only: the vertex shader must not be given it.
  const Program program =
      compiler.graphics("fullscreen.vert", "two_targets.frag", {SpecConstant::f(3, 0.75f)});
  gl::Texture first(GL_TEXTURE_2D, GL_RGBA32F, 4, 4, 1, "first");
  gl::Texture second(GL_TEXTURE_2D, GL_RGBA32F, 4, 4, 1, "second");
  gl::Framebuffer framebuffer;
  framebuffer.attach(GL_COLOR_ATTACHMENT0, first);
  framebuffer.attach(GL_COLOR_ATTACHMENT1, second);
  framebuffer.checkComplete("two targets");
  framebuffer.bind();
  glViewport(0, 0, 4, 4);
  GLuint vertexArray = 0;
  glCreateVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  program.use();
  glUniform1f(0, 0.5f);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteVertexArrays(1, &vertexArray);

  std::vector<float> pixels(4 * 4 * 4);
  const GLsizei bytes = GLsizei(pixels.size() * sizeof(float));
  glGetTextureImage(first.id(), 0, GL_RGBA, GL_FLOAT, bytes, pixels.data());
  EXPECT_EQ(pixels[0], 0.75f);
  EXPECT_EQ(pixels[1], 0.5f);
  EXPECT_EQ(pixels[2], 0.25f);
  EXPECT_EQ(pixels[63], 1.0f);
  glGetTextureImage(second.id(), 0, GL_RGBA, GL_FLOAT, bytes, pixels.data());
  EXPECT_EQ(pixels[60], 1.0f);
  EXPECT_EQ(pixels[63], 4.0f);
  checkGl("graphics");
}

TEST(ShaderCompiler, DefaultRootFollowsTheEnvironment) {
  std::optional<std::string> saved;
  if (const char* before = std::getenv("LPVLAB_SHADER_DIR")) saved = before;
  ::setenv("LPVLAB_SHADER_DIR", "/some/where", 1);
  EXPECT_EQ(ShaderCompiler::defaultRoot(), std::filesystem::path("/some/where"));
  ::unsetenv("LPVLAB_SHADER_DIR");
  EXPECT_EQ(ShaderCompiler::defaultRoot(), std::filesystem::path(LPVLAB_SOURCE_DIR) / "shaders");
  if (saved) ::setenv("LPVLAB_SHADER_DIR", saved->c_str(), 1);
}

}  // namespace
}  // namespace lpvlab
