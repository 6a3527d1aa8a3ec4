// A stand-in for Highway's libhwy.so.1, loaded only under Valgrind (scripts/valgrind-path-tracer.sh).
// Debian 12's libhwy runs RDTSCP in a static initialiser, which Valgrind 3.19 cannot execute, so
// no program linking OpenImageIO (-> libjxl -> libhwy) starts under memcheck. libjxl imports
// these five functions; lpvlab never decodes JPEG XL, so none of them is reached in the tests.
// Each behaves as documented all the same (aligned allocation, no SIMD target chosen).

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace hwy {

struct ChosenTarget {
  std::uint64_t mask[8];
};

void* AllocateAlignedBytes(std::size_t payload, void* (*)(void*, std::size_t), void*) {
  return std::aligned_alloc(128, (payload + 127) / 128 * 128);
}

void FreeAlignedBytes(const void* aligned, void (*)(void*, void*), void*) {
  std::free(const_cast<void*>(aligned));
}

struct AlignedDeleter {
  static void DeleteAlignedArray(void* aligned, void (*)(void*, void*), void*, void (*)(void*, std::size_t));
};

void AlignedDeleter::DeleteAlignedArray(void* aligned, void (*)(void*, void*), void*,
                                        void (*)(void*, std::size_t)) {
  std::free(aligned);
}

ChosenTarget& GetChosenTarget() {
  static ChosenTarget none{};
  return none;
}

std::int64_t SupportedTargets() { return 0; }

}  // namespace hwy
