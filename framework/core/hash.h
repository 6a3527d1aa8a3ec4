#pragma once
// Content hashes for cache keys and manifests: 64-bit FNV-1a, printed as 16 hex digits. Not
// cryptographic; it identifies content, it doesn't defend against tampering.

#include <cstdint>
#include <string>
#include <string_view>

namespace lpvlab {

class Hasher {
public:
  Hasher& bytes(const void* data, std::size_t size);
  Hasher& text(std::string_view s) { return bytes(s.data(), s.size()); }
  template <class T>
  Hasher& value(const T& v) { return bytes(&v, sizeof(T)); }
  std::uint64_t digest() const { return state_; }
  std::string hex() const;

private:
  std::uint64_t state_ = 14695981039346656037ull;
};

}  // namespace lpvlab
