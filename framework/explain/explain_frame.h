#pragma once
// lpvlab explain's oracles for one frame (docs/explain.md): after the pipeline rendered a frame
// with a light-grid method (LPV), its RSM's VPLs (rsm_vpl_subset.h) gathered exactly at each
// pixel with and without visibility (vpl_gather.h), and exact grids from the same VPLs
// (exact_grid.h) rendered by the method's own rendering, with and without visibility from the
// cells. Two independent VPL draws give each oracle twice: their mean is the oracle, their
// difference its noise.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "framework/explain/error_budget.h"
#include "framework/pipeline/indirect_method.h"

namespace lpvlab {

class Pipeline;
class EmbreeScene;

// Where the oracles' images are kept as they are rendered, so that an interrupted explanation
// resumes with those it has (each is a function of the frame, the VPLs and the seed alone).
struct ExplainCheckpoint {
  std::function<std::optional<Image>(const std::string& name)> load;  // nullopt: not saved yet
  std::function<void(const std::string& name, const Image& image)> save;
};

struct ExplainSettings {
  std::size_t vplsPerDraw = 2048;  // at most this many VPLs per draw (rsm_vpl_subset.h)
  std::uint64_t seed = 1;          // of the draws
  ExplainCheckpoint checkpoint;    // none by default
};

struct ExplainedFrame {
  ExplainImages images;
  Image mask;                    // the pixels the camera sees (1 channel), which every figure covers
  bool gridBlocksLight = false;  // the method's propagation blocks light (IndirectMethod)
  nlohmann::json vpls;           // how many, from how many covered texels, the block side
  nlohmann::json seconds;        // CPU wall time per oracle
  // The method's own light grid (IndirectMethod::dumpGrid) and the exact grid it is compared
  // with (with visibility where gridBlocksLight), the mean of the two draws', in the same layout:
  // the grid slices of figs. 8.9/8.10 beside their exact counterparts.
  GridDump methodGrid, exactGrid;
};

// The oracles of the frame `pipeline` rendered last; `scene` traces the shadow rays. Throws an
// Error when the method refuses (IndirectMethod::explainRefusal) or rendered no RSM.
ExplainedFrame explainFrame(Pipeline& pipeline, const EmbreeScene& scene,
                            const ExplainSettings& settings);

}  // namespace lpvlab
