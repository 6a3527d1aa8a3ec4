// LPV's side of lpvlab explain (framework/explain/, docs/explain.md): after a frame, the light
// grid replaced by an oracle's and rendered by the experiment's own rendering strategies.
#include "framework/core/error.h"
#include "framework/pipeline/dual_image.h"
#include "variants/methods/lpv/light_propagation_volumes.h"
#include "framework/pipeline/raster_inputs.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {

// The oracles model the RSM's VPLs, one bounce, read by rendering alone: what adds other light
// (the sky's columns, a second rendering strategy such as subsurface light) is refused by its key.
std::string LightPropagationVolumes::explainRefusal() const {
  if (!consumes().count(std::string(raster::kReflectiveShadowMaps.name)))
    return "injection \"" + strategies_.injection.front()->name() +
           "\" reads no RSM: the oracles gather the RSM's VPLs";
  if (strategies_.injection.size() > 1)
    return "[injection.also[0]] type = \"" + strategies_.injection[1]->name() +
           "\" adds light the oracles do not model (they gather the RSM's VPLs alone)";
  if (strategies_.rendering.size() > 1)
    return "[rendering.also[0]] type = \"" + strategies_.rendering[1]->name() +
           "\" adds light the oracles do not model (they replace the grid the first rendering reads)";
  return {};
}

bool LightPropagationVolumes::gridBlocksLight() const {
  return requirements_.has(kGeometryVolume);
}

Image LightPropagationVolumes::renderFromGrids(const GridFill& fill) {
  if (const std::string why = explainRefusal(); !why.empty()) throw Error("explain: " + why);
  if (!indirect_) throw Error("LPV: no frame has been rendered yet");
  for (LightGrid& grid : levels_) {
    const std::vector<float> values = fill(grid.geometry, grid.coefficients);
    if (values.size() != grid.floatsPerGrid())
      throw Error("explain: an oracle grid of " + std::to_string(values.size()) + " floats for a level of " +
                  std::to_string(grid.floatsPerGrid()));
    grid.accumulated.host() = values;
  }
  indirect_->zero();
  Frame f = this->frame(0);
  for (const auto& rendering : strategies_.rendering) rendering->render(f);
  return toImage(indirect_->hostRead(), 3);
}

}  // namespace lpvlab
