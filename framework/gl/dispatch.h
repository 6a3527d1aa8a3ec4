#pragma once
// Launching a compute kernel over a domain: enough work groups to cover every element (kernels
// return early for invocations past the domain's edge), then a barrier so the next stage sees the
// results.

#include <glm/glm.hpp>

namespace lpvlab {

// `domain` elements along x, y, z with the kernel's local_size `groupSize`; `barriers` is the
// glMemoryBarrier mask to issue afterwards.
void dispatchCovering(const glm::ivec3& domain, const glm::ivec3& groupSize, unsigned barriers);

}  // namespace lpvlab
