#pragma once
// Light Propagation Volumes as an indirect method ([indirect] method = "lpv", the default): per
// frame, (1) clearing the grids (placing cascade levels that follow what the camera sees), (2)
// occlusion (the GV's blocking potential), (3) injection, (4) propagation, (5) rendering of the
// indirect light. Stages 2-5 are the experiment's strategies ([occlusion], [injection],
// [propagation], [rendering]: strategy.h); the resources they pass each other
// (named_resources.h: the GV, the normal grid, ...) exist only if one strategy produces them and
// another uses them. With cascades (cascade.h) stages 1-4 run once per level, and injection ends
// by carrying each level's light into its parent. The grid's placement, SH order and cascades
// come from [grid] and [cascades] (PipelineSettings).
//
// Beside the IndirectMethod interface it gives what only a light grid has, for diagnostics and
// tests: the levels and their resources, grid read-back, the injection flux balance.

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "framework/pipeline/cascade.h"
#include "framework/pipeline/composition.h"
#include "framework/pipeline/indirect_method.h"
#include "framework/pipeline/light_grid.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

// Flux bookkeeping of injection (W, summed over RGB): what the RSMs reflect, and what the grid
// holds after injection (the difference fell outside the grid).
struct InjectionBalance {
  double rsmFlux = 0.0;
  double gridFlux = 0.0;
  // Flux each injection strategy added (its experiment table, e.g. "injection.also[0]"), in order.
  std::vector<std::pair<std::string, double>> byInjection;
};

class LightPropagationVolumes final : public IndirectMethod {
public:
  // Reads its strategies from the experiment's [occlusion], [injection], [propagation] and
  // [rendering] tables (`indirect` is the [indirect] table, whose document holds them).
  explicit LightPropagationVolumes(Params& indirect);
  // A composition made in code (tests).
  explicit LightPropagationVolumes(Strategies strategies);
  ~LightPropagationVolumes() override;

  std::vector<std::string> stageNames() const override;
  std::set<std::string> consumes() const override;
  std::set<std::string> cpuStages() const override { return cpuStages_; }
  // Whether a strategy runs on GL (which reads the G-buffer and the light maps as textures).
  bool readsRasterImagesOnGl() const override;
  void check(const PipelineSettings& settings) const override;
  void prepare(const MethodSetup& setup) override;
  void render(MethodFrame& frame) override;
  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) override;
  void setCamera(const Camera& camera) override;
  bool keepsStateBetweenFrames() const override;

  std::map<std::string, std::vector<WorkCount>> work() const override;
  nlohmann::json workReport(bool glKernels) const override;
  std::size_t memoryBytes() const override;
  nlohmann::json memoryReport() const override;
  nlohmann::json computeReport() const override;
  nlohmann::json describe(const std::map<std::string, double>& medianStageMs) const override;
  std::vector<std::string> summaryKeys() const override;
  nlohmann::json audit() override;
  std::string explainRefusal() const override;
  Image renderFromGrids(const GridFill& fill) override;
  bool gridBlocksLight() const override;
  std::string derivativeRefusal(const std::string& key) const override;
  FrameDerivatives renderDerivatives(const std::vector<std::string>& seeds,
                                     const std::function<void()>& renderFrame) override;

  // The light grids, finest first, where the last frame placed them.
  const std::vector<LightGrid>& levels() const { return levels_; }
  // A level's resources (named_resources.h), e.g. to read the injected normal grid back.
  const ResourceTable& resources(int level = 0) const { return resources_.at(std::size_t(level)); }
  // A level's current / accumulated coefficients as floats (grid.glsl layout); level 0 is the
  // finest (the only one without cascades).
  std::vector<float> readGrid(bool accumulated, int level = 0) const;
  // The accumulated grid of every level: [level][channel][coefficient][z][y][x], W/sr.
  bool hasLightGrid() const override { return true; }
  GridDump dumpGrid() const override;
  // Re-runs clearing and injection alone after a frame and measures the flux balance on the
  // coarsest level (which holds the whole scene; reads the RSM and the grid back to the CPU).
  InjectionBalance measureInjection();
  // Cells one propagation iteration updates, over every level (for cell-iterations/s).
  std::size_t propagatedCells() const;
  const Requirements& requirements() const { return requirements_; }
  const Strategies& strategies() const { return strategies_; }

private:
  Frame frame(int level);
  FrameShape frameShape() const;  // what the strategies' work depends on
  // Places the finer cascade levels around `focus` ("depth" placement), or by the eye rule.
  void placeLevels(const std::optional<glm::vec3>& focus = std::nullopt);
  void clearGrids();
  void injectAll(int level);

  Strategies strategies_;
  PipelineSettings settings_;  // from prepare
  Camera camera_;
  const SceneGpu* scene_ = nullptr;
  const LightMaps* lightMaps_ = nullptr;
  Requirements requirements_;
  std::vector<LightGrid> levels_;         // finest first
  std::vector<ResourceTable> resources_;  // per level: the resources the composition uses
  std::unique_ptr<CascadeCarry> carry_;   // with carrying cascades only
  std::set<std::string> consumed_;        // the raster inputs the strategies read
  std::set<std::string> cpuStages_;       // stages with a strategy on the CPU backend
  int geometryVersion_ = 0;  // moves of the scene's geometry so far (Frame::geometryVersion)
  // The last frame's inputs (they live as long as the pipeline): measureInjection's frame.
  const GBuffer* gbuffer_ = nullptr;
  HostReadback* host_ = nullptr;
  DualImage* indirect_ = nullptr;
  bool keepInjected_ = false;  // render keeps the injected grid (renderDerivatives)
  std::vector<float> injected_;
};

}  // namespace lpvlab
