// Occlusion "none": no geometry volume; light propagates through surfaces (the standard method
// without the GV, thesis 4.4 with occlusion switched off). Allocates nothing.

#include <string>

#include "framework/pipeline/strategy.h"

namespace lpvlab {
namespace {

class NoOcclusion final : public OcclusionStrategy {
public:
  explicit NoOcclusion(Params&) {}
  int maxShOrder() const override { return 3; }  // touches no light grid
  std::string cpuRefusal(const Requirements&) const override { return {}; }  // computes nothing
  void prepare(const StrategySetup&) override {}
  void inject(Frame&) override {}
};

LPVLAB_REGISTER(OcclusionStrategy, "none", "no geometry volume: light passes through surfaces",
                NoOcclusion);

}  // namespace
}  // namespace lpvlab
