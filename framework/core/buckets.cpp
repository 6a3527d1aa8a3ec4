#include "framework/core/buckets.h"

namespace lpvlab {

Buckets bucketByKey(const std::vector<int>& keyOf, int keys) {
  Buckets b;
  b.first.assign(std::size_t(keys) + 1, 0);
  for (int key : keyOf)
    if (key >= 0) ++b.first[std::size_t(key) + 1];
  for (int key = 0; key < keys; ++key) b.first[std::size_t(key) + 1] += b.first[std::size_t(key)];
  std::vector<std::size_t> next(b.first.begin(), b.first.end() - 1);
  b.order.resize(b.first.back());
  for (std::size_t item = 0; item < keyOf.size(); ++item)
    if (keyOf[item] >= 0) b.order[next[std::size_t(keyOf[item])]++] = item;
  return b;
}

}  // namespace lpvlab
