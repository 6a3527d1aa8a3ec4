// LPV's derivatives through a frame (light_propagation_volumes.h, dual_frame.h): after a frame,
// the stages from the first seeded one run again on dual numbers.
#include <algorithm>

#include "framework/core/error.h"
#include "framework/pipeline/dual_frame.h"
#include "variants/methods/lpv/light_propagation_volumes.h"

namespace lpvlab {

std::string LightPropagationVolumes::derivativeRefusal(const std::string& key) const {
  const std::size_t dot = key.rfind('.');
  if (dot == std::string::npos) return "'" + key + "' is not <table>.<name>";
  const std::string table = key.substr(0, dot), name = key.substr(dot + 1);
  const Strategy* owner = nullptr;
  for (const auto& [t, strategy] : strategies_.all())
    if (t == table) owner = strategy;
  if (!owner) return "the experiment has no [" + table + "] strategy";
  const std::vector<std::string> names = owner->differentiableParameters();
  if (std::find(names.begin(), names.end(), name) == names.end())
    return table + " \"" + owner->name() + "\" carries no derivatives of '" + name + "'";
  if (levels_.size() != 1) return "derivatives are carried through one cascade level only";
  if (stageOfTable(table) != "indirect" && !strategies_.propagation->differentiates())
    return "propagation \"" + strategies_.propagation->name() + "\" has no kernel on dual numbers";
  for (const auto& rendering : strategies_.rendering)
    if (!rendering->differentiates())
      return "rendering \"" + rendering->name() + "\" has no kernel on dual numbers";
  return {};
}

IndirectMethod::FrameDerivatives LightPropagationVolumes::renderDerivatives(
    const std::vector<std::string>& seeds, const std::function<void()>& renderFrame) {
  keepInjected_ = true;
  try {
    renderFrame();
  } catch (...) {
    keepInjected_ = false;
    throw;
  }
  keepInjected_ = false;
  Frame frame = this->frame(0);
  const int w = settings_.width, h = settings_.height;
  DualTexelImage indirect{w, h,
                          std::vector<glm::vec<4, Dual>>(std::size_t(w) * h, glm::vec<4, Dual>(Dual(0.0)))};
  DualFrame dual{.frame = frame, .seeds = seeds, .table = "occlusion", .indirect = &indirect};
  bool upstream = false;  // a stage before rendering is seeded
  for (const std::string& seed : seeds) upstream |= stageOfTable(seed) != "indirect";
  if (upstream) {
    strategies_.occlusion->injectDual(dual);
    dual.injected = constantDuals(injected_);
    dual.table = "propagation";
    strategies_.propagation->propagateDual(dual);
  } else {
    dual.accumulated = constantDuals(levels_.front().accumulated.hostRead());
  }
  for (const auto& [table, strategy] : strategies_.all()) {
    if (stageOfTable(table) != "indirect") continue;
    dual.table = table;
    static_cast<RenderingStrategy*>(strategy)->renderDual(dual);
  }
  // Top row first, as the pipeline's readOutputs gives the indirect image.
  FrameDerivatives out{Image(w, h, 3), std::vector<Image>(seeds.size(), Image(w, h, 3))};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec<4, Dual>& texel = indirect.texels[std::size_t(y) * w + x];
      for (int c = 0; c < 3; ++c) {
        out.indirect.at(x, h - 1 - y, c) = float(texel[c].a);
        for (std::size_t j = 0; j < seeds.size(); ++j)
          out.derivatives[j].at(x, h - 1 - y, c) = float(texel[c].v[j]);
      }
    }
  return out;
}

}  // namespace lpvlab
