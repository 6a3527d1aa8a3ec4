// NumPy's .npy files (framework/io/npy.h): what writeNpy writes, readNpy reads back bit for bit,
// in every shape; the header is the format's own (the magic, version 1.0, a dictionary naming
// '<f4', C order and the shape, padded so the data start at a multiple of 64 bytes), which
// numpy.load reads (tests/experiment/grid_dump_test.cpp has numpy read a dump when python3-numpy
// is there); anything else is refused naming the file.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "framework/core/error.h"
#include "framework/io/npy.h"
#include "temp_dir.h"

namespace lpvlab {
namespace {

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Npy, RoundTripsEveryShapeBitForBit) {
  test::TempDir dir;
  const float inf = std::numeric_limits<float>::infinity();
  for (const NpyArray& array : {NpyArray{{5}, {1.0f, -2.5f, 1e-38f, inf, 3e38f}},
                                NpyArray{{2, 3}, {0, 1, 2, 3, 4, 5}},
                                NpyArray{{2, 1, 2, 2}, {1, 2, 3, 4, 5, 6, 7, 8}},
                                NpyArray{{0, 4}, {}}}) {
    const std::string path = dir.file("a.npy");
    writeNpy(path, array);
    const NpyArray back = readNpy(path);
    EXPECT_EQ(back.shape, array.shape);
    ASSERT_EQ(back.values.size(), array.values.size());
    for (std::size_t i = 0; i < array.values.size(); ++i)
      EXPECT_EQ(std::memcmp(&back.values[i], &array.values[i], sizeof(float)), 0) << i;
  }
}

TEST(Npy, TheHeaderIsNumpysOwn) {
  test::TempDir dir;
  const std::string path = dir.file("g.npy");
  writeNpy(path, {{2, 3}, {0, 1, 2, 3, 4, 5}});
  const std::string bytes = bytesOf(path);
  ASSERT_GT(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
  EXPECT_EQ(bytes[6], 1);
  EXPECT_EQ(bytes[7], 0);
  const std::size_t headerLength = std::uint8_t(bytes[8]) | (std::uint8_t(bytes[9]) << 8);
  EXPECT_EQ((10 + headerLength) % 64, 0u) << "data aligned to 64 bytes";
  const std::string dict = bytes.substr(10, headerLength);
  EXPECT_EQ(dict.substr(0, dict.find('}') + 1), "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }");
  EXPECT_EQ(dict.back(), '\n');
  EXPECT_EQ(bytes.size(), 10 + headerLength + 6 * sizeof(float));
  writeNpy(path, {{7}, std::vector<float>(7, 0.0f)});
  EXPECT_NE(bytesOf(path).find("'shape': (7, )"), std::string::npos) << "a 1-D shape is a tuple";
}

TEST(Npy, RefusesWhatItCannotReadAndValuesThatDoNotFitTheShape) {
  test::TempDir dir;
  EXPECT_THROW(writeNpy(dir.file("x.npy"), {{2, 2}, {1, 2, 3}}), Error);
  std::ofstream(dir.file("text.npy")) << "not numpy";
  EXPECT_THROW(readNpy(dir.file("text.npy")), Error);
  EXPECT_THROW(readNpy(dir.file("missing.npy")), Error);
  writeNpy(dir.file("short.npy"), {{4}, {1, 2, 3, 4}});
  const std::string bytes = bytesOf(dir.file("short.npy"));
  std::ofstream(dir.file("cut.npy"), std::ios::binary) << bytes.substr(0, bytes.size() - 3);
  try {
    readNpy(dir.file("cut.npy"));
    FAIL() << "a cut file was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("cut.npy"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace lpvlab
