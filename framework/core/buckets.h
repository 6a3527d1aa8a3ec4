#pragma once
// Items grouped by a small integer key with a stable counting sort: the CPU kernels' way of
// summing many contributions per cell without atomics (each cell then adds its own items, in
// item order, so a sum does not depend on the thread count).

#include <cstddef>
#include <vector>

namespace lpvlab {

struct Buckets {
  std::vector<std::size_t> order;  // item indices, by key, in item order within a key
  std::vector<std::size_t> first;  // key k's items: order[first[k] .. first[k + 1])
};

// Items 0 .. keyOf.size() - 1 grouped by keyOf[item] in [0, keys); an item whose key is negative
// is left out.
Buckets bucketByKey(const std::vector<int>& keyOf, int keys);

}  // namespace lpvlab
