// Propagation "injected_only": no propagation at all, the light grid's injected light is what
// the rendering reads (the pipeline starts the accumulated grid with it). The zero-iteration
// baseline of an ablation, and the smallest strategy there is: it reads its [propagation] keys
// (none; any other key is an error naming it), says what it can run with, and registers itself
// by name. `lpvlab list` then lists it, and an experiment picks it with
// [propagation] type = "injected_only".

#include <string>

#include "framework/core/parameters.h"
#include "framework/pipeline/strategy.h"

namespace {

class InjectedOnly final : public lpvlab::PropagationStrategy {
public:
  explicit InjectedOnly(lpvlab::Params&) {}
  int maxShOrder() const override { return 3; }  // touches no coefficient
  std::string cpuRefusal(const lpvlab::Requirements&) const override { return {}; }  // no kernel
  void prepare(const lpvlab::StrategySetup&) override {}
  void propagate(lpvlab::Frame&) override {}
  int iterations() const override { return 0; }
};

LPVLAB_REGISTER(lpvlab::PropagationStrategy, "injected_only",
                "no propagation: the injected light alone (an out-of-tree example)", InjectedOnly);

}  // namespace
