// The strategies' defaults (strategy.h) that are not inline.
#include "framework/pipeline/strategy.h"

#include "framework/core/error.h"

namespace lpvlab {

void PropagationStrategy::propagateDual(DualFrame&) {
  throw Error("propagation \"" + name() + "\" has no kernel on dual numbers");
}

void RenderingStrategy::renderDual(DualFrame&) {
  throw Error("rendering \"" + name() + "\" has no kernel on dual numbers");
}

}  // namespace lpvlab
