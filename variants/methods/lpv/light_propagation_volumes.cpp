// LPV's frame: its construction from the experiment's tables, preparation and stages
// (light_propagation_volumes.h). Its reports are in lpv_reports.cpp, its derivatives in
// lpv_derivatives.cpp.
#include "variants/methods/lpv/light_propagation_volumes.h"

#include <algorithm>

#include "framework/core/error.h"
#include "framework/math/cascade_placement.h"
#include "framework/pipeline/raster_inputs.h"
#include "variants/resources/sky_light.h"

namespace lpvlab {

namespace {

// A stage with a main table and optional [[<stage>.also]] tables (e.g. sky light added to the RSM
// injection), each with its own type and parameters; the main one runs first.
template <class Interface>
std::vector<std::unique_ptr<Interface>> createStage(Params table, const std::string& defaultType) {
  std::vector<std::unique_ptr<Interface>> strategies;
  strategies.push_back(Registry<Interface>::instance().create(table, defaultType));
  for (Params& also : table.tables("also"))
    strategies.push_back(Registry<Interface>::instance().create(also, defaultType));
  return strategies;
}

Strategies readStrategies(Params& indirect) {
  Params experiment = indirect.document();
  Strategies strategies;
  Params occlusion = experiment.table("occlusion");
  strategies.injection = createStage<InjectionStrategy>(experiment.table("injection"), "rsm_vpl");
  strategies.occlusion = Registry<OcclusionStrategy>::instance().create(occlusion, "none");
  Params propagation = experiment.table("propagation");
  strategies.propagation = Registry<PropagationStrategy>::instance().create(propagation, "standard");
  strategies.rendering = createStage<RenderingStrategy>(experiment.table("rendering"), "trilinear");
  return strategies;
}

// The raster inputs the strategies consume or read (Strategy::declare).
std::set<std::string> rasterInputsOf(const Strategies& strategies) {
  std::set<std::string> inputs;
  for (const auto& [table, strategy] : strategies.all()) {
    ResourceUses uses;
    strategy->declare(uses);
    for (const ResourceUses::Use& use : uses.uses())
      if (use.kind != ResourceUses::Kind::Produces && raster::isRasterInput(use.name))
        inputs.insert(use.name);
  }
  return inputs;
}

// The world positions of the surfaces the G-buffer's pixels see (where cascades follow them),
// from its position image on the host (read back once, or made there by the ray-cast raster).
std::vector<glm::vec3> visiblePositions(const HostImage& gbufferPositions) {
  std::vector<glm::vec3> positions;
  for (const glm::vec4& texel : gbufferPositions.texels)
    if (texel.w > 0.0f) positions.emplace_back(texel);
  return positions;
}

}  // namespace

LightPropagationVolumes::LightPropagationVolumes(Params& indirect)
    : LightPropagationVolumes(readStrategies(indirect)) {}

LightPropagationVolumes::LightPropagationVolumes(Strategies strategies)
    : strategies_(std::move(strategies)), consumed_(rasterInputsOf(strategies_)) {
  setRegisteredName("lpv");
}

LightPropagationVolumes::~LightPropagationVolumes() = default;

std::vector<std::string> LightPropagationVolumes::stageNames() const {
  return {"clear", "occlusion", "injection", "propagation", "indirect"};
}

std::set<std::string> LightPropagationVolumes::consumes() const { return consumed_; }

void LightPropagationVolumes::check(const PipelineSettings& settings) const {
  // "auto" is resolved against the GL renderer when the run starts; "cpu" is checked here.
  resolveRequirements(strategies_, settings.shOrder, skyLightUses(settings.skyRadiance),
                      settings.cascades.levels,
                      settings.backend == "cpu" ? ComputeBackend::Cpu : ComputeBackend::Gl, settings.gl);
}

bool LightPropagationVolumes::keepsStateBetweenFrames() const {
  const auto strategies = strategies_.all();
  return std::any_of(strategies.begin(), strategies.end(),
                     [](auto& s) { return s.second->keepsStateBetweenFrames(); });
}

void LightPropagationVolumes::prepare(const MethodSetup& setup) {
  settings_ = setup.settings;
  camera_ = setup.camera;
  scene_ = &setup.sceneGpu;
  lightMaps_ = &setup.lightMaps;
  requirements_ = resolveRequirements(strategies_, settings_.shOrder,
                                      skyLightUses(settings_.skyRadiance),
                                      settings_.cascades.levels, setup.backend, settings_.gl);
  for (const auto& [table, strategy] : strategies_.all())
    if (strategy->runsOnCpu(requirements_)) cpuStages_.insert(stageOfTable(table));
  // Every level has the grid's cell counts, so strategies size their scratch once, from `grid`.
  const GridGeometry& grid = settings_.grid;
  for (int level = 0; level < requirements_.cascadeLevels; ++level) {
    levels_.emplace_back(grid, requirements_.shOrder);
    ResourceTable& table = resources_.emplace_back();
    const ResourceSetup resourceSetup{grid, requirements_.shOrder, requirements_.backend};
    for (const auto& [name, allocate] : requirements_.resources)
      table.adopt(name, allocate(resourceSetup));
  }
  placeLevels();
  if (levels_.size() > 1 && settings_.cascades.carry) {
    // The carry has a CPU kernel: it follows the backend (and runs in the injection stage).
    const bool carryOnCpu = requirements_.backend != ComputeBackend::Gl;
    carry_ = std::make_unique<CascadeCarry>(setup.shaders, requirements_.shOrder, carryOnCpu);
    if (carryOnCpu) cpuStages_.insert("injection");
  }
  const StrategySetup strategySetup{.shaders = setup.shaders,
                                    .grid = grid,
                                    .requirements = requirements_,
                                    .scene = scene_,
                                    .lightMaps = lightMaps_,
                                    .imageSize = {settings_.width, settings_.height},
                                    .skyRadiance = settings_.skyRadiance};
  for (const auto& [table, strategy] : strategies_.all()) strategy->prepare(strategySetup);
  checkGl("LPV setup");
}

Frame LightPropagationVolumes::frame(int level) {
  if (!gbuffer_) throw Error("LPV: no frame has been rendered yet");
  const std::size_t l = std::size_t(level);
  return Frame{.scene = scene_,
               .camera = &camera_,
               .gbuffer = *gbuffer_,
               .lightMaps = *lightMaps_,
               .lightGrid = levels_[l],
               .indirect = *indirect_,
               .resources = &resources_[l],
               .host = host_,
               .levels = levels_,
               .cascadeBlendCells = settings_.cascades.blendCells,
               .level = level,
               .geometryVersion = geometryVersion_};
}

void LightPropagationVolumes::setCamera(const Camera& camera) {
  camera_ = camera;
  placeLevels();
}

void LightPropagationVolumes::moveScene(const Scene&, bool, bool geometryMoved) {
  if (geometryMoved) ++geometryVersion_;
}

void LightPropagationVolumes::placeLevels(const std::optional<glm::vec3>& focus) {
  const std::vector<GridGeometry> placed =
      focus ? placeCascadeLevels(settings_.grid, int(levels_.size()), *focus,
                                 settings_.cascades.snap)
            : placeCascadeLevels(settings_.grid, int(levels_.size()), camera_.position,
                                 camera_.forward, settings_.cascades.viewShift,
                                 settings_.cascades.snap);
  for (std::size_t level = 0; level < levels_.size(); ++level) {
    levels_[level].geometry = placed[level];
    resources_[level].place(placed[level]);
  }
}

std::size_t LightPropagationVolumes::propagatedCells() const {
  std::size_t cells = 0;
  for (const LightGrid& grid : levels_) cells += std::size_t(grid.geometry.cellCount());
  return cells;
}

void LightPropagationVolumes::clearGrids() {
  for (LightGrid& grid : levels_) grid.current.zero();
  for (ResourceTable& resources : resources_) resources.clear();
}

void LightPropagationVolumes::injectAll(int level) {
  Frame frame = this->frame(level);
  for (const auto& injection : strategies_.injection) injection->inject(frame);
}

void LightPropagationVolumes::render(MethodFrame& frame) {
  gbuffer_ = &frame.gbuffer;
  host_ = &frame.host;
  indirect_ = &frame.indirect;
  const int levels = int(levels_.size());
  frame.stage("clear", [&] {
    if (levels > 1 && settings_.cascades.placement == CascadePlacement::Depth)
      placeLevels(visibleFocus(visiblePositions(frame.host.image(frame.gbuffer.position))));
    clearGrids();
  });
  frame.stage("occlusion", [&] {
    for (int level = 0; level < levels; ++level) {
      Frame f = this->frame(level);
      strategies_.occlusion->inject(f);
    }
  });
  frame.stage("injection", [&] {
    for (int level = 0; level < levels; ++level) injectAll(level);
    if (carry_)
      for (int level = 0; level + 1 < levels; ++level)
        carry_->carry(levels_[std::size_t(level)], levels_[std::size_t(level) + 1]);
    // The accumulated light starts as the injected light (thesis 6.9.1).
    for (LightGrid& grid : levels_) grid.accumulated.copyFrom(grid.current);
    if (keepInjected_) injected_ = levels_.front().current.hostRead();
  });
  frame.stage("propagation", [&] {
    for (int level = 0; level < levels; ++level) {
      Frame f = this->frame(level);
      strategies_.propagation->propagate(f);
    }
  });
  frame.stage("indirect", [&] {
    Frame f = this->frame(0);
    for (const auto& rendering : strategies_.rendering) rendering->render(f);
  });
}

LPVLAB_REGISTER_READING(IndirectMethod, "lpv",
                        "Light Propagation Volumes: the strategies of [occlusion], [injection], "
                        "[propagation] and [rendering] on the light grid of [grid] and [cascades]",
                        LightPropagationVolumes, "grid", "cascades", "occlusion", "injection",
                        "propagation", "rendering");

}  // namespace lpvlab
