#pragma once
// Requirements for one strategy tested alone, as the composition check would make them with the
// test standing in for the rest of the composition: the test provides every resource the
// strategy consumes; of those it only reads or produces, the ones named in `alsoUsed` (the test
// provides what it reads, or uses what it produces).

#include <algorithm>
#include <string>
#include <vector>

#include "framework/pipeline/strategy.h"

namespace lpvlab::test {

inline Requirements standInRequirements(const Strategy& strategy, int shOrder,
                                        const std::vector<std::string>& alsoUsed = {}) {
  ResourceUses uses;
  strategy.declare(uses);
  Requirements requirements;
  requirements.shOrder = shOrder;
  for (const ResourceUses::Use& use : uses.uses()) {
    const bool named = std::find(alsoUsed.begin(), alsoUsed.end(), use.name) != alsoUsed.end();
    if (use.kind == ResourceUses::Kind::Consumes || named)
      requirements.resources.emplace(use.name, ResourceAllocator{});
  }
  return requirements;
}

}  // namespace lpvlab::test
