#pragma once
// LPV's own view of a run in tests (variants/methods/lpv/light_propagation_volumes.h): its grids,
// strategies, read-back and injection balance, which no other method has and the pipeline does
// not carry.

#include <memory>
#include <utility>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "variants/methods/lpv/light_propagation_volumes.h"

namespace lpvlab::test {

// The run's LPV method: a std::bad_cast, failing the test, when the run's method is another.
inline LightPropagationVolumes& lpvOf(Pipeline& pipeline) {
  return dynamic_cast<LightPropagationVolumes&>(pipeline.method());
}
inline const LightPropagationVolumes& lpvOf(const Pipeline& pipeline) {
  return dynamic_cast<const LightPropagationVolumes&>(pipeline.method());
}

// The strategies an experiment read for LPV (its method must be LPV).
inline const Strategies& lpvStrategies(const Experiment& e) {
  return dynamic_cast<const LightPropagationVolumes&>(*e.method).strategies();
}

// LPV running a composition made in code.
inline std::unique_ptr<IndirectMethod> lpvMethod(Strategies strategies) {
  return std::make_unique<LightPropagationVolumes>(std::move(strategies));
}

}  // namespace lpvlab::test
