#include <gtest/gtest.h>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

// Injection splats many VPLs into one cell with atomicAdd on floats; every add must land. Floats
// count integers exactly up to 2^24, so N adds of 1.0 must sum to exactly N.
TEST(FloatAtomics, EveryAddLandsInBuffersAndImages) {
  test::glTestContext();
  ShaderCompiler compiler(test::testShaderRoot());
  const Program program = compiler.compute("float_atomics.comp");
  constexpr GLuint kGroups = 4096, kInvocations = kGroups * 256;  // 2^20
  gl::Buffer sum(sizeof(float), "atomics.sum");
  sum.bindStorage(0);
  gl::Texture image(GL_TEXTURE_2D, GL_R32F, 1, 1, 1, "atomics.image");
  const float zero = 0.0f;
  glClearTexImage(image.id(), 0, GL_RED, GL_FLOAT, &zero);
  glBindImageTexture(0, image.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
  program.use();
  glDispatchCompute(kGroups, 1, 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  checkGl("float atomics");

  float bufferSum = 0.0f, imageSum = 0.0f;
  sum.download(&bufferSum, sizeof bufferSum);
  glGetTextureImage(image.id(), 0, GL_RED, GL_FLOAT, sizeof imageSum, &imageSum);
  EXPECT_EQ(bufferSum, float(kInvocations));
  EXPECT_EQ(imageSum, float(kInvocations));
}

}  // namespace
}  // namespace lpvlab
