#include "framework/io/npy.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <numeric>
#include <regex>
#include <sstream>

#include "framework/core/atomic_file.h"
#include "framework/core/error.h"

namespace lpvlab {

namespace {

static_assert(std::endian::native == std::endian::little, "npy: '<f4' is written as the host's floats");

constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicBytes = 6;

std::size_t product(const std::vector<std::size_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), std::size_t(1), std::multiplies<>());
}

// The header dictionary, padded with spaces and a newline so that the data starts at a multiple
// of 64 bytes (the format's alignment).
std::string header(const std::vector<std::size_t>& shape) {
  std::ostringstream dict;
  dict << "{'descr': '<f4', 'fortran_order': False, 'shape': (";
  for (std::size_t i = 0; i < shape.size(); ++i) dict << shape[i] << (shape.size() == 1 || i + 1 < shape.size() ? ", " : "");
  dict << "), }";
  std::string text = dict.str();
  const std::size_t preamble = kMagicBytes + 2 + 2;  // magic, version, header length
  const std::size_t total = (preamble + text.size() + 1 + 63) / 64 * 64;
  text.append(total - preamble - text.size() - 1, ' ');
  return text + "\n";
}

}  // namespace

void writeNpy(const std::string& path, const NpyArray& array) {
  if (product(array.shape) != array.values.size())
    throw Error(path + ": an array of " + std::to_string(array.values.size()) +
                " values does not have the shape it is written with");
  const std::string dict = header(array.shape);
  writeAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    out.write(kMagic, kMagicBytes);
    const char version[2] = {1, 0};
    out.write(version, 2);
    const std::uint16_t length = std::uint16_t(dict.size());
    out.write(reinterpret_cast<const char*>(&length), 2);
    out.write(dict.data(), std::streamsize(dict.size()));
    out.write(reinterpret_cast<const char*>(array.values.data()),
              std::streamsize(array.values.size() * sizeof(float)));
    if (!out) throw Error(path + ": could not be written");
  });
}

NpyArray readNpy(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be opened");
  char magic[kMagicBytes + 2];
  std::uint16_t length = 0;
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(&length), 2);
  if (!in || std::memcmp(magic, kMagic, kMagicBytes) != 0 || magic[kMagicBytes] != 1)
    throw Error(path + ": not a version 1 .npy file");
  std::string dict(length, '\0');
  in.read(dict.data(), length);
  static const std::regex form(R"(\{'descr': '<f4', 'fortran_order': False, 'shape': \(([0-9, ]*)\), \}\s*)");
  std::smatch match;
  if (!std::regex_match(dict, match, form))
    throw Error(path + ": not a C-order array of little-endian float32 (header " + dict + ")");
  NpyArray array;
  std::istringstream dims(match[1].str());
  for (std::string dim; std::getline(dims, dim, ',');)
    if (dim.find_first_not_of(' ') != std::string::npos) array.shape.push_back(std::stoull(dim));
  array.values.resize(product(array.shape));
  in.read(reinterpret_cast<char*>(array.values.data()), std::streamsize(array.values.size() * sizeof(float)));
  if (!in) throw Error(path + ": ends before its " + std::to_string(array.values.size()) + " values");
  return array;
}

}  // namespace lpvlab
