// The light grid's storage on GL and the host (framework/gl/dual_buffer.h): whichever side
// wrote last is what the other side sees when it is next asked for, through every way in.

#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/gl/dual_buffer.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

// What GL holds, read through the buffer's name (bringing GL up to date first, as a kernel's
// binding would).
std::vector<float> onGl(const DualBuffer& buffer) {
  std::vector<float> values(buffer.size() / sizeof(float));
  const GLuint id = buffer.id();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(id, 0, GLsizeiptr(buffer.size()), values.data());
  return values;
}

std::vector<float> ramp(std::size_t n, float start) {
  std::vector<float> v(n);
  std::iota(v.begin(), v.end(), start);
  return v;
}

TEST(DualBuffer, EachSideSeesWhatTheOtherWroteLast) {
  test::glTestContext();
  constexpr std::size_t kFloats = 64;
  DualBuffer buffer(kFloats * sizeof(float), "test");
  EXPECT_EQ(buffer.hostRead(), std::vector<float>(kFloats, 0.0f));  // a new buffer is zeros

  // The host writes: a download reads it, and GL has it once bound.
  std::vector<float>& host = buffer.host();
  host = ramp(kFloats, 1.0f);
  std::vector<float> read(kFloats);
  buffer.download(read.data(), read.size() * sizeof(float));
  EXPECT_EQ(read, ramp(kFloats, 1.0f));
  EXPECT_EQ(onGl(buffer), ramp(kFloats, 1.0f));

  // GL writes (an upload): the host reads it back.
  const std::vector<float> fromGl = ramp(kFloats, 100.0f);
  buffer.upload(fromGl.data(), fromGl.size() * sizeof(float));
  EXPECT_EQ(buffer.hostRead(), fromGl);

  // A copy takes the up-to-date side: the host's here.
  buffer.host()[3] = -7.0f;
  DualBuffer copy(kFloats * sizeof(float), "copy");
  copy.copyFrom(buffer);
  std::vector<float> expected = fromGl;
  expected[3] = -7.0f;
  EXPECT_EQ(copy.hostRead(), expected);
  EXPECT_EQ(onGl(copy), expected);
  // ... and GL's when GL wrote last.
  buffer.upload(fromGl.data(), fromGl.size() * sizeof(float));
  copy.copyFrom(buffer);
  EXPECT_EQ(copy.hostRead(), fromGl);

  // Zero clears both.
  copy.zero();
  EXPECT_EQ(copy.hostRead(), std::vector<float>(kFloats, 0.0f));
  EXPECT_EQ(onGl(copy), std::vector<float>(kFloats, 0.0f));
}

TEST(DualBuffer, CopiesOfDifferentSizesAreErrors) {
  test::glTestContext();
  DualBuffer a(16 * sizeof(float), "a"), b(8 * sizeof(float), "b");
  EXPECT_THROW(a.copyFrom(b), Error);
  EXPECT_THROW(DualBuffer(6, "odd"), Error);
}

}  // namespace
}  // namespace lpvlab
