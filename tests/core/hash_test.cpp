#include "framework/core/hash.h"

#include <gtest/gtest.h>

namespace lpvlab {
namespace {

// Published FNV-1a 64-bit test vectors (Fowler/Noll/Vo reference).
TEST(Hasher, MatchesKnownVectors) {
  EXPECT_EQ(Hasher().hex(), "cbf29ce484222325");
  EXPECT_EQ(Hasher().text("a").hex(), "af63dc4c8601ec8c");
  EXPECT_EQ(Hasher().text("foobar").hex(), "85944171f73967e8");
  EXPECT_EQ(Hasher().text("foobar").digest(), 0x85944171f73967e8ull);
}

TEST(Hasher, HexIsSixteenDigitsEvenWithLeadingZeros) {
  // Search a value whose digest starts with a zero nibble, so zero padding is exercised.
  for (int i = 0;; ++i) {
    Hasher h;
    h.value(i);
    if (h.digest() >> 60 == 0) {
      EXPECT_EQ(h.hex().size(), 16u);
      EXPECT_EQ(h.hex()[0], '0');
      break;
    }
  }
}

TEST(Hasher, ChainingEqualsConcatenation) {
  EXPECT_EQ(Hasher().text("foo").text("bar").digest(), Hasher().text("foobar").digest());
  const char bytes[] = {'f', 'o', 'o'};
  EXPECT_EQ(Hasher().bytes(bytes, 3).text("bar").digest(), Hasher().text("foobar").digest());
}

TEST(Hasher, DistinguishesOrder) {
  EXPECT_NE(Hasher().text("ab").digest(), Hasher().text("ba").digest());
}

}  // namespace
}  // namespace lpvlab
