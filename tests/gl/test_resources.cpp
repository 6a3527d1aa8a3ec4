#include <gtest/gtest.h>

#include <functional>
#include <numeric>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/resources.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

using gl::Buffer;
using gl::Framebuffer;
using gl::Texture;

class Resources : public testing::Test {
protected:
  void SetUp() override { test::glTestContext(); }
};

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no Error)";
}

TEST_F(Resources, BufferRoundTrip) {
  std::vector<float> data(1000);
  std::iota(data.begin(), data.end(), -3.5f);
  Buffer buffer(data.size() * sizeof(float), "round trip", data.data());
  EXPECT_EQ(buffer.size(), data.size() * sizeof(float));
  std::vector<float> back(data.size());
  buffer.download(back.data(), back.size() * sizeof(float));
  EXPECT_EQ(back, data);

  const float patch[2] = {42.0f, -42.0f};
  buffer.upload(patch, sizeof patch, 10 * sizeof(float));
  float two[2] = {};
  buffer.download(two, sizeof two, 10 * sizeof(float));
  EXPECT_EQ(two[0], 42.0f);
  EXPECT_EQ(two[1], -42.0f);

  buffer.zero();
  buffer.download(back.data(), back.size() * sizeof(float));
  EXPECT_EQ(back, std::vector<float>(data.size(), 0.0f));
}

TEST_F(Resources, NewBufferIsZeroOfAnySize) {
  Buffer buffer(7, "odd size");
  std::vector<unsigned char> back(7, 0xff);
  buffer.download(back.data(), back.size());
  EXPECT_EQ(back, std::vector<unsigned char>(7, 0));
}

TEST_F(Resources, BufferRangesAreChecked) {
  Buffer buffer(16, "small");
  char bytes[32] = {};
  const std::string message = messageOf([&] { buffer.upload(bytes, 8, 12); });
  EXPECT_NE(message.find("small: upload of 8 bytes at offset 12"), std::string::npos) << message;
  EXPECT_NE(messageOf([&] { buffer.download(bytes, 17); }).find("small"), std::string::npos);
  EXPECT_NE(messageOf([] { Buffer(0, "empty"); }).find("empty"), std::string::npos);
}

TEST_F(Resources, MovedBufferKeepsItsObject) {
  Buffer a(4, "a");
  const GLuint id = a.id();
  Buffer b(std::move(a));
  EXPECT_EQ(b.id(), id);
  EXPECT_EQ(a.id(), 0u);
  EXPECT_EQ(b.label(), "a");
}

TEST_F(Resources, TextureBytes) {
  EXPECT_EQ(Texture(GL_TEXTURE_2D, GL_RGBA16F, 64, 32, 1, "rsm.flux").bytes(), 64u * 32 * 8);
  EXPECT_EQ(Texture(GL_TEXTURE_3D, GL_R32F, 8, 8, 8, "gv").bytes(), 8u * 8 * 8 * 4);
  EXPECT_EQ(Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA8, 4, 4, 3, "layers").bytes(), 4u * 4 * 3 * 4);
  EXPECT_EQ(Texture(GL_TEXTURE_3D, GL_RGBA32F, 4, 4, 4, "lpv").bytes(), 4u * 4 * 4 * 16);
  const std::pair<GLenum, std::size_t> sizes[] = {
      {GL_R32F, 4}, {GL_RG32F, 8}, {GL_RGBA32F, 16}, {GL_RGBA16F, 8}, {GL_RGBA8, 4},
      {GL_SRGB8_ALPHA8, 4}, {GL_DEPTH_COMPONENT32F, 4}, {GL_DEPTH_COMPONENT24, 4}, {GL_R32UI, 4}};
  for (const auto& [format, bytes] : sizes) EXPECT_EQ(Texture::texelBytes(format), bytes);
  const std::string message = messageOf([] { Texture(GL_TEXTURE_2D, GL_RGB8, 4, 4, 1, "rgb"); });
  EXPECT_EQ(message.rfind("rgb: texture format 0x8051", 0), 0u) << message;  // GL_RGB8
}

TEST_F(Resources, IncompleteFramebufferNamesItsLabel) {
  Framebuffer empty;
  const std::string message = messageOf([&] { empty.checkComplete("rsm of light 0"); });
  EXPECT_NE(message.find("rsm of light 0: framebuffer incomplete"), std::string::npos) << message;
  EXPECT_NE(message.find("MISSING_ATTACHMENT"), std::string::npos) << message;
}

TEST_F(Resources, FramebufferWithColourDepthAndLayer) {
  Texture colour(GL_TEXTURE_2D, GL_RGBA32F, 8, 8, 1, "colour");
  Texture layers(GL_TEXTURE_2D_ARRAY, GL_RGBA16F, 8, 8, 4, "layers");
  Texture depth(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, 8, 8, 1, "depth");
  Framebuffer framebuffer;
  framebuffer.attach(GL_COLOR_ATTACHMENT0, colour);
  framebuffer.attach(GL_COLOR_ATTACHMENT1, layers, 2);
  framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
  EXPECT_NO_THROW(framebuffer.checkComplete("g-buffer"));

  Framebuffer shadow;  // depth only, as a shadow map
  shadow.attach(GL_DEPTH_ATTACHMENT, depth);
  EXPECT_NO_THROW(shadow.checkComplete("shadow map"));
}

TEST_F(Resources, CheckGlReportsErrorsWithDebugOutput) {
  EXPECT_NO_THROW(checkGl("before"));
  GLuint missing = 0;
  glCreateBuffers(1, &missing);
  glDeleteBuffers(1, &missing);
  const float value = 1.0f;
  glNamedBufferSubData(missing, 0, sizeof value, &value);  // a deleted buffer
  const std::string message = messageOf([] { checkGl("uploading"); });
  EXPECT_EQ(message.rfind("uploading: GL_INVALID_OPERATION", 0), 0u) << message;
  EXPECT_NE(message.find("glNamedBufferSubData"), std::string::npos) << message;
  EXPECT_NO_THROW(checkGl("after"));
}

}  // namespace
}  // namespace lpvlab
