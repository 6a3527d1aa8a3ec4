#include "framework/pipeline/pipeline.h"

#include <algorithm>
#include <chrono>

#include "framework/core/error.h"
#include "framework/math/cascade_placement.h"
#include "framework/math/shared.h"

namespace lpvlab {

namespace {

// An RGBA image (bottom row first, as GL stores it) flipped to top row first, keeping `channels`
// of its RGBA from `firstChannel` on.
Image toImage(const HostImage& rgba, int channels, int firstChannel = 0) {
  const int w = rgba.width, h = rgba.height;
  Image image(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        image.at(x, h - 1 - y, c) = rgba.texels[std::size_t(y) * w + x][firstChannel + c];
  return image;
}

// A float texture's level 0, the same way.
Image readTexture(const gl::Texture& texture, int channels, int firstChannel = 0) {
  return toImage(downloadImage(texture), channels, firstChannel);
}

// The world positions of the surfaces the G-buffer's pixels see (where cascades follow them).
std::vector<glm::vec3> visiblePositions(const GBuffer& gbuffer) {
  std::vector<glm::vec4> texels(std::size_t(gbuffer.width) * gbuffer.height);
  glGetTextureImage(gbuffer.position.id(), 0, GL_RGBA, GL_FLOAT,
                    GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
  std::vector<glm::vec3> positions;
  for (const glm::vec4& texel : texels)
    if (texel.w > 0.0f) positions.emplace_back(texel);
  return positions;
}

// The stage whose time a strategy's work shows in, from its experiment table
// (Strategies::all): "injection.also[0]" -> "injection", "rendering" -> "indirect".
std::string stageOfTable(const std::string& table) {
  const std::string stage = table.substr(0, table.find('.'));
  return stage == "rendering" ? "indirect" : stage;
}

double gridFlux(const std::vector<float>& coefficients, int cells, int coefficientCount) {
  double flux = 0.0;
  for (int channel = 0; channel < LightGrid::kChannels; ++channel)
    for (int cell = 0; cell < cells; ++cell)
      flux += shared::shIntegral(glm::dvec4(
          coefficients[shared::coefficientIndex(channel, 0, coefficientCount, cell, cells)], 0, 0, 0));
  return flux;
}

}  // namespace

const std::vector<std::string>& Pipeline::stageNames() {
  static const std::vector<std::string> names = {"shadow_maps", "rsm",       "gbuffer",
                                                 "direct",      "clear",     "occlusion",
                                                 "injection",   "propagation", "indirect"};
  return names;
}

Pipeline::Pipeline(const Scene& scene, const Camera& camera, const PipelineSettings& settings,
                   Strategies strategies, ShaderCompiler& shaders)
    : settings_(settings),
      camera_(camera),
      lights_(scene.lights),
      sceneBounds_(scene.bounds()),
      strategies_(std::move(strategies)) {
  const bool emissiveLight = strategies_.method && strategies_.method->lightsWithEmissiveSurfaces() &&
                             std::any_of(scene.materials.begin(), scene.materials.end(),
                                         [](const Material& m) { return m.emits(); });
  if (scene.lights.empty() && !emissiveLight)
    throw Error(scene.source + ": the scene has no light the LPV pipeline can use (point, spot or "
                "directional; emissive surfaces are shown but light nothing in LPV runs); add one "
                "under [[lights]] in the experiment");
  const ComputeBackend backend =
      resolveBackend(settings.backend, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  IndirectMethod* method = strategies_.method.get();
  // With another indirect method the LPV strategies are not run: nothing of theirs is checked,
  // allocated or prepared.
  if (method)
    requirements_.backend = backend;
  else
    requirements_ = resolveRequirements(strategies_, settings.shOrder, settings.skyRadiance,
                                        settings.cascades.levels, backend);

  if (!method)
    for (const auto& [table, strategy] : strategies_.all())
      if (strategy->runsOnCpu(requirements_)) cpuStages_.insert(stageOfTable(table));
  if (method && method->runsOnCpu())
    for (const std::string& stage : method->stageNames()) cpuStages_.insert(stage);

  scene_ = std::make_unique<SceneGpu>(scene);
  const bool emissive = std::any_of(scene.materials.begin(), scene.materials.end(),
                                    [](const Material& m) { return m.emits(); });
  gbufferPass_ = std::make_unique<GBufferPass>(shaders, settings.width, settings.height, emissive);
  lightMapsPass_ = std::make_unique<LightMapsPass>(shaders, lightViews(), settings.rsmResolution,
                                                   settings.shadowResolution);
  // Direct light has a CPU kernel for every composition: it follows the backend.
  direct_ = std::make_unique<DirectLighting>(shaders, settings.shadow,
                                             requirements_.backend != ComputeBackend::Gl);
  if (direct_->onCpu()) cpuStages_.insert("direct");
  directImage_ = DualImage(settings.width, settings.height, "direct");
  indirectImage_ = DualImage(settings.width, settings.height, "indirect");
  if (method) {
    method->prepare(MethodSetup{.scene = scene, .settings = settings_, .shaders = shaders});
    checkGl("indirect method setup");
    return;
  }
  // Every level has the grid's cell counts, so strategies size their scratch once, from `grid`.
  for (int level = 0; level < requirements_.cascadeLevels; ++level) {
    levels_.emplace_back(settings.grid, requirements_.shOrder);
    ResourceTable& table = resources_.emplace_back();
    const ResourceSetup setup{settings.grid, requirements_.shOrder, requirements_.backend};
    for (const auto& [name, allocate] : requirements_.resources) table.adopt(name, allocate(setup));
  }
  placeLevels();
  if (levels_.size() > 1 && settings.cascades.carry) {
    // The carry has a CPU kernel: it follows the backend (and runs in the injection stage).
    const bool carryOnCpu = requirements_.backend != ComputeBackend::Gl;
    carry_ = std::make_unique<CascadeCarry>(shaders, requirements_.shOrder, carryOnCpu);
    if (carryOnCpu) cpuStages_.insert("injection");
  }
  const StrategySetup setup{.shaders = shaders,
                            .grid = settings.grid,
                            .requirements = requirements_,
                            .scene = scene_.get(),
                            .lightMaps = &lightMapsPass_->lightMaps(),
                            .imageSize = {settings.width, settings.height},
                            .skyRadiance = settings.skyRadiance};
  for (const auto& [table, strategy] : strategies_.all()) strategy->prepare(setup);
  checkGl("pipeline setup");
}

Pipeline::~Pipeline() = default;

template <class F>
void Pipeline::stage(const std::string& name, FrameTimes& times, F&& work) {
  const auto start = std::chrono::steady_clock::now();
  gpuTimer_.begin(name);
  work();
  gpuTimer_.end();
  glFinish();
  times.wallMs[name] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (std::find(times.order.begin(), times.order.end(), name) == times.order.end())
    times.order.push_back(name);
}

Frame Pipeline::frame(int level) {
  const std::size_t l = std::size_t(level);
  return Frame{.scene = scene_.get(),
               .camera = &camera_,
               .gbuffer = gbufferPass_->gbuffer(),
               .lightMaps = lightMapsPass_->lightMaps(),
               .lightGrid = levels_[l],
               .indirect = indirectImage_,
               .resources = &resources_[l],
               .host = &hostReadback_,
               .levels = levels_,
               .cascadeBlendCells = settings_.cascades.blendCells,
               .level = level,
               .geometryVersion = geometryVersion_};
}

void Pipeline::setCamera(const Camera& camera) {
  camera_ = camera;
  placeLevels();
  if (settings_.directional.followWidth > 0.0f) lightMapsPass_->setViews(lightViews());
}

void Pipeline::moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) {
  if (geometryMoved) {
    scene_->updateGeometry(scene);
    ++geometryVersion_;
  }
  if (strategies_.method) strategies_.method->moveScene(scene, lightsMoved, geometryMoved);
  if (!lightsMoved && !geometryMoved) return;
  lights_ = scene.lights;
  sceneBounds_ = scene.bounds();
  lightMapsPass_->setViews(lightViews());
}

std::optional<DirectionalFollow> directionalFollow(const PipelineSettings& settings,
                                                   const Camera& camera) {
  const DirectionalViewSettings& directional = settings.directional;
  if (directional.followWidth <= 0.0f) return std::nullopt;
  // The box's centre is where the eye rule centres the finer cascade levels: view_shift of the
  // box's width ahead of the eye (cascade_placement.h).
  const float halfWidth = 0.5f * directional.followWidth;
  return DirectionalFollow{
      .centre = camera.position +
                camera.forward * (settings.cascades.viewShift * directional.followWidth),
      .halfWidth = halfWidth,
      .texel = directional.snap ? directionalSnapStep(halfWidth, settings.rsmResolution,
                                                      settings.shadowResolution)
                                : 0.0f};
}

LightViews Pipeline::lightViews() const {
  return buildLightViews(lights_, sceneBounds_, directionalFollow(settings_, camera_));
}

void Pipeline::placeLevels(const std::optional<glm::vec3>& focus) {
  if (levels_.empty()) return;  // another indirect method: no light grid
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

std::size_t Pipeline::propagatedCells() const {
  std::size_t cells = 0;
  for (const LightGrid& grid : levels_) cells += std::size_t(grid.geometry.cellCount());
  return cells;
}

void Pipeline::clearGrids() {
  for (LightGrid& grid : levels_) grid.current.zero();
  for (ResourceTable& resources : resources_) resources.clear();
}

void Pipeline::injectAll(int level) {
  Frame frame = this->frame(level);
  for (const auto& injection : strategies_.injection) injection->inject(frame);
}

FrameTimes Pipeline::renderFrame() {
  FrameTimes times;
  hostReadback_.newFrame();
  if (settings_.directLight)
    stage("shadow_maps", times, [&] { lightMapsPass_->renderShadowMaps(*scene_, extras_); });
  if (!strategies_.method || strategies_.method->readsReflectiveShadowMaps())
    stage("rsm", times, [&] { lightMapsPass_->renderRsms(*scene_, extras_); });
  stage("gbuffer", times, [&] { gbufferPass_->render(*scene_, camera_, extras_); });
  if (settings_.directLight)
    stage("direct", times, [&] {
      direct_->render(gbufferPass_->gbuffer(), lightMapsPass_->lightMaps(), directImage_,
                      hostReadback_);
    });
  if (strategies_.method) {
    indirectImage_.zero();
    MethodFrame frame{.camera = camera_,
                      .gbuffer = gbufferPass_->gbuffer(),
                      .lightMaps = lightMapsPass_->lightMaps(),
                      .host = hostReadback_,
                      .indirect = indirectImage_,
                      .stage = [&](const std::string& name, const std::function<void()>& work) {
                        stage(name, times, work);
                      }};
    strategies_.method->render(frame);
  } else {
    renderLpvStages(times);
  }
  times.stageMs = gpuTimer_.collectMs();
  for (const auto& [stage, _] : times.stageMs) times.clock[stage] = kGlTimerQuery;
  // A stage whose strategies run on the CPU backend spends its time on the CPU, which GL
  // timestamps do not see: its time is its wall time (transfers to and from GL included).
  for (const std::string& stage : cpuStages_)
    if (const auto wall = times.wallMs.find(stage); wall != times.wallMs.end()) {
      times.stageMs[stage] = wall->second;
      times.clock[stage] = kCpuWallClock;
    }
  checkGl("frame");
  return times;
}

void Pipeline::renderLpvStages(FrameTimes& times) {
  const int levels = int(levels_.size());
  stage("clear", times, [&] {
    if (levels > 1 && settings_.cascades.placement == CascadePlacement::Depth)
      placeLevels(visibleFocus(visiblePositions(gbufferPass_->gbuffer())));
    clearGrids();
  });
  stage("occlusion", times, [&] {
    for (int level = 0; level < levels; ++level) {
      Frame frame = this->frame(level);
      strategies_.occlusion->inject(frame);
    }
  });
  stage("injection", times, [&] {
    for (int level = 0; level < levels; ++level) injectAll(level);
    if (carry_)
      for (int level = 0; level + 1 < levels; ++level)
        carry_->carry(levels_[std::size_t(level)], levels_[std::size_t(level) + 1]);
    // The accumulated light starts as the injected light (thesis 6.9.1).
    for (LightGrid& grid : levels_) grid.accumulated.copyFrom(grid.current);
    if (keepInjected_) injected_ = levels_.front().current.hostRead();
  });
  stage("propagation", times, [&] {
    for (int level = 0; level < levels; ++level) {
      Frame frame = this->frame(level);
      strategies_.propagation->propagate(frame);
    }
  });
  stage("indirect", times, [&] {
    indirectImage_.zero();  // on the side the first rendering strategy asks for
    Frame frame = this->frame(0);
    for (const auto& rendering : strategies_.rendering) rendering->render(frame);
  });
}

std::vector<NamedImage> Pipeline::readOutputs() const {
  const GBuffer& g = gbufferPass_->gbuffer();
  // From the side that wrote them last (read back only if that was GL).
  Image direct = toImage(directImage_.hostRead(), 3);
  Image indirect = toImage(indirectImage_.hostRead(), 3);
  Image combined = direct;
  for (std::size_t i = 0; i < combined.pixels.size(); ++i) combined.pixels[i] += indirect.pixels[i];
  return {{"direct", std::move(direct)},
          {"indirect", std::move(indirect)},
          {"combined", std::move(combined)},
          {"albedo", readTexture(g.albedo, 3)},
          {"normal", readTexture(g.normal, 3)},
          {"depth", readTexture(g.normal, 1, 3)}};
}

std::vector<float> Pipeline::readGrid(bool accumulated, int level) const {
  if (levels_.empty()) throw Error("the run's indirect method has no light grid");
  const LightGrid& grid = levels_.at(std::size_t(level));
  std::vector<float> data(grid.floatsPerGrid());
  (accumulated ? grid.accumulated : grid.current).download(data.data(), data.size() * sizeof(float));
  return data;
}

const LightMaps& Pipeline::lightMaps() const { return lightMapsPass_->lightMaps(); }

InjectionBalance Pipeline::measureInjection() {
  if (strategies_.method) throw Error("the run's indirect method injects nothing into a grid");
  const int coarsest = int(levels_.size()) - 1;
  Frame frame = this->frame(coarsest);
  const LightGrid& grid = levels_.back();
  clearGrids();
  strategies_.occlusion->inject(frame);
  InjectionBalance balance;
  const auto all = strategies_.all();
  for (std::size_t i = 0; i < strategies_.injection.size(); ++i) {
    strategies_.injection[i]->inject(frame);
    const double total =
        gridFlux(readGrid(false, coarsest), grid.geometry.cellCount(), grid.coefficients);
    balance.byInjection.emplace_back(all[i].first, total - balance.gridFlux);
    balance.gridFlux = total;
  }
  const LightMaps& maps = lightMapsPass_->lightMaps();
  std::vector<float> flux(std::size_t(maps.rsmResolution) * maps.rsmResolution * maps.views * 4);
  glGetTextureImage(maps.rsmFlux.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(flux.size() * sizeof(float)),
                    flux.data());
  for (std::size_t i = 0; i < flux.size(); i += 4) balance.rsmFlux += flux[i] + flux[i + 1] + flux[i + 2];
  return balance;
}

nlohmann::json Pipeline::computeReport() const {
  nlohmann::json report = {{"backend", backendName(requirements_.backend)},
                           {"raster_passes", "gl"},
                           {"direct", direct_->onCpu() ? "cpu" : "gl"}};
  if (const IndirectMethod* method = strategies_.method.get()) {
    report["indirect_method"] = {{"name", method->name()},
                                 {"runs_on", method->runsOnCpu() ? "cpu" : "gl"}};
    return report;
  }
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [table, strategy] : strategies_.all())
    stages[table] = strategy->runsOnCpu(requirements_) ? "cpu" : "gl";
  report["strategies"] = stages;
  return report;
}

nlohmann::json Pipeline::workReport(bool glKernels) const {
  const LightMaps& maps = lightMapsPass_->lightMaps();
  const double pixels = double(settings_.width) * settings_.height;
  const double rsmTexels = double(maps.views) * maps.rsmResolution * maps.rsmResolution;
  const auto entry = [](const WorkCount& w) {
    return nlohmann::json{{"unit", w.unit},
                          {"units", w.units},
                          {"multiply_adds_per_unit", w.multiplyAddsPerUnit},
                          {"bytes_per_unit", w.bytesPerUnit},
                          {"multiply_adds", w.units * w.multiplyAddsPerUnit},
                          {"bytes", w.units * w.bytesPerUnit}};
  };
  nlohmann::json report = nlohmann::json::object();
  const double shadowTexels = double(maps.views) * maps.shadowResolution * maps.shadowResolution;
  report["shadow_maps"] = {entry({"texel", shadowTexels})};
  if (!strategies_.method || strategies_.method->readsReflectiveShadowMaps())
    report["rsm"] = {entry({"texel", rsmTexels})};
  report["gbuffer"] = {entry({"pixel", pixels})};
  report["direct"] = {entry(direct_->work(pixels, maps.lightCount, glKernels))};
  if (const IndirectMethod* method = strategies_.method.get()) {
    // A method counts what its last frame did, on whichever side it runs.
    for (const auto& [stage, counts] : method->work()) {
      report[stage] = nlohmann::json::array();
      for (const WorkCount& w : counts) report[stage].push_back(entry(w));
    }
    return report;
  }
  FrameShape shape;
  shape.cells = double(settings_.grid.cellCount());
  shape.levels = int(levels_.size());
  shape.coefficients = levels_.front().coefficients;
  shape.rsmTexels = rsmTexels;
  shape.pixels = pixels;
  Requirements requirements = requirements_;
  if (glKernels) requirements.backend = ComputeBackend::Gl;
  for (const auto& [table, strategy] : strategies_.all()) {
    const std::string stage = stageOfTable(table);
    if (!report.contains(stage)) report[stage] = nlohmann::json::array();
    const std::vector<WorkCount> counts = strategy->work(shape, requirements);
    if (counts.empty() && strategy->name() != "none")
      report[stage].push_back({{"table", table}, {"not_counted", strategy->name()}});
    for (const WorkCount& w : counts) report[stage].push_back(entry(w));
  }
  return report;
}

nlohmann::json Pipeline::memoryReport() const {
  const auto sum = [](const auto& items, auto bytesOf) {
    std::size_t total = 0;
    for (const auto& item : items) total += bytesOf(item);
    return total;
  };
  nlohmann::json bytes = {
      {"scene", scene_->memoryBytes()},
      {"gbuffer", gbufferPass_->gbuffer().memoryBytes()},
      {"light_maps", lightMapsPass_->lightMaps().memoryBytes()},
      {"light_grid", sum(levels_, [](const LightGrid& g) { return g.memoryBytes(); })},
      {"output_images", directImage_.memoryBytes() + indirectImage_.memoryBytes()}};
  for (const ResourceTable& resources : resources_)
    for (const auto& [name, size] : resources.memoryBytes())
      bytes[name] = bytes.value(name, std::size_t(0)) + size;
  if (strategies_.method)
    bytes["indirect_method"] = strategies_.method->memoryBytes();
  else
    for (const auto& [table, strategy] : strategies_.all())
      bytes[table] = bytes.value(table, std::size_t(0)) + strategy->memoryBytes();
  std::size_t total = 0;
  for (const auto& [name, value] : bytes.items()) total += value.get<std::size_t>();
  bytes["total"] = total;
  return bytes;
}

}  // namespace lpvlab
