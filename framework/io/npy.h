#pragma once
// NumPy's .npy format (version 1.0, numpy.org/doc/stable/reference/generated/numpy.lib.format.html)
// for arrays of 32-bit floats: what numpy.load, and most array tools, read without lpvlab. Written
// atomically (framework/core/atomic_file.h); little-endian ('<f4'), C order.

#include <cstddef>
#include <string>
#include <vector>

namespace lpvlab {

struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<float> values;  // C order: the last axis varies fastest
};

// Throws an Error when the values are not the product of the shape.
void writeNpy(const std::string& path, const NpyArray& array);
// Reads what writeNpy writes (float32, C order, little-endian; any shape); throws an Error
// naming the file for anything else.
NpyArray readNpy(const std::string& path);

}  // namespace lpvlab
