#include "framework/core/hash.h"

#include <cstdio>

namespace lpvlab {

Hasher& Hasher::bytes(const void* data, std::size_t size) {
  // FNV-1a: xor the byte in first, then multiply; the order is what distinguishes it from FNV-1.
  constexpr std::uint64_t prime = 1099511628211ull;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    state_ ^= p[i];
    state_ *= prime;
  }
  return *this;
}

std::string Hasher::hex() const {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(state_));
  return buffer;
}

}  // namespace lpvlab
