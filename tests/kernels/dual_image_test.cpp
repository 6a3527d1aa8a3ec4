// A frame's output images on GL and the host (framework/pipeline/dual_image.h): whichever side
// wrote last is what the other side sees when it is next asked for, zero() reaches both sides,
// and the host copy is allocated only when the host asks for it.

#include <vector>

#include <gtest/gtest.h>

#include "framework/pipeline/dual_image.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// What GL holds, read through the texture (bringing GL up to date first).
std::vector<glm::vec4> onGl(DualImage& image) {
  std::vector<glm::vec4> texels(std::size_t(image.width()) * image.height());
  const GLuint id = image.texture().id();
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  glGetTextureImage(id, 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
  return texels;
}

// GL writes every texel (as a kernel would), through the texture.
void fillOnGl(DualImage& image, float value) {
  const float rgba[4] = {value, value + 1.0f, value + 2.0f, value + 3.0f};
  glClearTexImage(image.texture().id(), 0, GL_RGBA, GL_FLOAT, rgba);
}

TEST(DualImage, EachSideSeesWhatTheOtherWroteLast) {
  test::glTestContext();
  constexpr int kWidth = 5, kHeight = 3;
  const std::size_t texels = std::size_t(kWidth) * kHeight;
  DualImage image(kWidth, kHeight, "test");
  EXPECT_EQ(image.memoryBytes(), texels * sizeof(glm::vec4));  // no host copy yet
  EXPECT_EQ(onGl(image), std::vector<glm::vec4>(texels, glm::vec4(0.0f)));  // a new image is zeros

  // GL writes: the host reads it back.
  fillOnGl(image, 1.0f);
  const HostImage& host = image.hostRead();
  EXPECT_EQ(host.width, kWidth);
  EXPECT_EQ(host.height, kHeight);
  EXPECT_EQ(host.texels, std::vector<glm::vec4>(texels, glm::vec4(1, 2, 3, 4)));
  EXPECT_EQ(image.memoryBytes(), 2 * texels * sizeof(glm::vec4));

  // The host writes: GL has it when next asked for.
  image.host().texels[4] = glm::vec4(-7.0f);
  std::vector<glm::vec4> expected(texels, glm::vec4(1, 2, 3, 4));
  expected[4] = glm::vec4(-7.0f);
  EXPECT_EQ(onGl(image), expected);
  EXPECT_EQ(image.hostRead().texels, expected);
}

TEST(DualImage, ZeroReachesWhicheverSideIsAskedForNext) {
  test::glTestContext();
  constexpr int kWidth = 4, kHeight = 4;
  const std::vector<glm::vec4> zeros(std::size_t(kWidth) * kHeight, glm::vec4(0.0f));
  DualImage image(kWidth, kHeight, "test");

  // Written on GL, zeroed: the host reads zeros (not GL's old texels), and so does GL.
  fillOnGl(image, 5.0f);
  image.zero();
  EXPECT_EQ(image.hostRead().texels, zeros);
  EXPECT_EQ(onGl(image), zeros);

  // Written on the host, zeroed, then the host adds to it (as a CPU rendering strategy does):
  // GL then sees only the addition.
  image.host().texels[1] = glm::vec4(9.0f);
  image.zero();
  image.host().texels[2] += glm::vec4(0.5f);
  std::vector<glm::vec4> expected = zeros;
  expected[2] = glm::vec4(0.5f);
  EXPECT_EQ(onGl(image), expected);

  // GL adds after a zero: the host reads GL's texels.
  image.zero();
  fillOnGl(image, 2.0f);
  EXPECT_EQ(image.hostRead().texels, std::vector<glm::vec4>(zeros.size(), glm::vec4(2, 3, 4, 5)));
}

}  // namespace
}  // namespace lpvlab
