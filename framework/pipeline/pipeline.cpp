#include "framework/pipeline/pipeline.h"

#include <algorithm>
#include <chrono>

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/raster_inputs.h"

namespace lpvlab {

const std::vector<std::string>& Pipeline::stageNames() {
  static const std::vector<std::string> names = {"shadow_maps", "rsm", "gbuffer", "direct"};
  return names;
}

namespace {

// The settings with `gl` as the context the pipeline runs in has it.
PipelineSettings withGlKnown(PipelineSettings settings) {
  settings.gl = GlContext::glLoaded();
  return settings;
}

}  // namespace

Pipeline::Pipeline(const Scene& scene, const Camera& camera, const PipelineSettings& settings,
                   std::unique_ptr<IndirectMethod> method, ShaderCompiler& shaders, RasterPlan raster)
    : settings_(withGlKnown(settings)),
      camera_(camera),
      lights_(scene.lights),
      sceneBounds_(scene.bounds()),
      method_(std::move(method)),
      consumed_(method_->consumes()),
      raster_(std::move(raster)) {
  for (const std::string& name : method_->stageNames())
    if (name == kMethodTime || name == kSharedTime || name == kTotalTime ||
        std::find(stageNames().begin(), stageNames().end(), name) != stageNames().end())
      throw Error("indirect method \"" + method_->name() + "\": its stage \"" + name +
                  "\" has the name of the pipeline's own stage or of a sum of stages");
  const bool emissive = std::any_of(scene.materials.begin(), scene.materials.end(),
                                    [](const Material& m) { return m.emits(); });
  if (scene.lights.empty() && !(emissive && renders(raster::kEmission.name)))
    throw Error(scene.source + ": the scene has no light the indirect method \"" + method_->name() +
                "\" can use (point, spot or directional; emissive surfaces are shown but light "
                "nothing in its runs); add one under [[lights]] in the experiment");
  backend_ = resolveBackend(settings.backend, GlContext::currentRenderer());
  scene_ = std::make_unique<SceneGpu>(scene);
  gbufferPass_ = std::make_unique<GBufferPass>(shaders, settings.width, settings.height, emissive);
  lightMapsPass_ = std::make_unique<LightMapsPass>(shaders, lightViews(), settings.rsmResolution,
                                                   settings.shadowResolution);
  // Direct light has a CPU kernel for every composition: it follows the backend.
  direct_ = std::make_unique<DirectLighting>(shaders, settings.shadow, backend_ != ComputeBackend::Gl,
                                             raster_.host.get());
  if (direct_->onCpu()) cpuStages_.insert("direct");
  directImage_ = DualImage(settings.width, settings.height, "direct");
  indirectImage_ = DualImage(settings.width, settings.height, "indirect");
  method_->prepare(MethodSetup{.scene = scene,
                               .settings = settings_,
                               .shaders = shaders,
                               .backend = backend_,
                               .sceneGpu = *scene_,
                               .lightMaps = lightMapsPass_->lightMaps(),
                               .camera = camera_});
  for (const std::string& stage : method_->cpuStages()) cpuStages_.insert(stage);
  for (const std::string& pass : raster_.hostPasses) cpuStages_.insert(pass);
  if (!GlContext::glLoaded()) {  // without GL every stage runs on the CPU
    cpuStages_.insert(stageNames().begin(), stageNames().end());
    for (const std::string& stage : method_->stageNames()) cpuStages_.insert(stage);
  }
  uploadRasterImages_ = !raster_.hostPasses.empty() &&
                        ((settings.directLight && !direct_->onCpu()) || method_->readsRasterImagesOnGl());
  checkGl("pipeline setup");
}

void Pipeline::addExtraGeometry(const ExtraGeometry* extra) {
  if (raster_.host)
    throw Error("key 'compute.raster': the raster passes or shadow rays on the CPU (" +
                raster_.host->name() + ") see the scene's meshes alone, not light-field billboards; "
                "use raster = \"gl\" and shadows = \"map\"");
  extras_.push_back(extra);
}

bool Pipeline::renders(std::string_view rasterInput) const {
  if (rasterInput == raster::kGBuffer.name) return true;  // the run's AOVs
  if (rasterInput == raster::kShadowMaps.name && settings_.directLight && !settings_.shadow.rays)
    return true;
  return consumed_.count(std::string(rasterInput)) > 0;
}

Pipeline::~Pipeline() = default;

template <class F>
void Pipeline::stage(const std::string& name, FrameTimes& times, F&& work) {
  const auto start = std::chrono::steady_clock::now();
  gpuTimer_.begin(name);
  work();
  gpuTimer_.end();
  gl::finish();
  times.wallMs[name] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (std::find(times.order.begin(), times.order.end(), name) == times.order.end())
    times.order.push_back(name);
}

void Pipeline::setCamera(const Camera& camera) {
  camera_ = camera;
  method_->setCamera(camera);
  if (settings_.directional.followWidth > 0.0f) lightMapsPass_->setViews(lightViews());
}

void Pipeline::moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) {
  if (geometryMoved) scene_->updateGeometry(scene);
  if (geometryMoved && raster_.host) raster_.host->moveGeometry(scene);
  method_->moveScene(scene, lightsMoved, geometryMoved);
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

FrameTimes Pipeline::renderFrame() {
  FrameTimes times;
  hostReadback_.newFrame();
  if (renders(raster::kShadowMaps.name)) stage("shadow_maps", times, [&] { renderShadowMaps(); });
  if (renders(raster::kReflectiveShadowMaps.name)) stage("rsm", times, [&] { renderRsms(); });
  stage("gbuffer", times, [&] { renderGBuffer(); });
  if (settings_.directLight)
    stage("direct", times, [&] {
      direct_->render(gbufferPass_->gbuffer(), lightMapsPass_->lightMaps(), directImage_,
                      hostReadback_);
    });
  indirectImage_.zero();  // lazily: on the side the method writes first
  MethodFrame frame{.camera = camera_,
                    .gbuffer = gbufferPass_->gbuffer(),
                    .lightMaps = lightMapsPass_->lightMaps(),
                    .host = hostReadback_,
                    .indirect = indirectImage_,
                    .stage = [&](const std::string& name, const std::function<void()>& work) {
                      times.methodStages.insert(name);
                      stage(name, times, work);
                    }};
  method_->render(frame);
  times.stageMs = gpuTimer_.collectMs();
  for (const auto& [stage, _] : times.stageMs) times.clock[stage] = kGlTimerQuery;
  // A stage whose kernels run on the CPU backend spends its time on the CPU, which GL
  // timestamps do not see: its time is its wall time (transfers to and from GL included).
  for (const std::string& stage : cpuStages_)
    if (const auto wall = times.wallMs.find(stage); wall != times.wallMs.end()) {
      times.stageMs[stage] = wall->second;
      times.clock[stage] = kCpuWallClock;
    }
  checkGl("frame");
  return times;
}

void Pipeline::renderShadowMaps() {
  if (!raster_.hostPasses.count(kShadowMapPass)) return lightMapsPass_->renderShadowMaps(*scene_, extras_);
  const LightMaps& maps = lightMapsPass_->lightMaps();
  HostDepthImage& depths = hostReadback_.writtenDepth(maps.shadowDepth);
  raster_.host->renderShadowMaps(maps.records, maps.shadowResolution, depths);
  if (uploadRasterImages_) uploadDepth(depths, maps.shadowDepth);
}

void Pipeline::renderRsms() {
  if (!raster_.hostPasses.count(kRsmPass)) return lightMapsPass_->renderRsms(*scene_, extras_);
  const LightMaps& maps = lightMapsPass_->lightMaps();
  const HostRsmTargets out{.position = &hostReadback_.written(maps.rsmPosition),
                           .normal = &hostReadback_.written(maps.rsmNormal),
                           .flux = &hostReadback_.written(maps.rsmFlux)};
  raster_.host->renderRsms(maps.records, maps.rsmResolution, out);
  if (uploadRasterImages_) {
    uploadLayers(*out.position, maps.rsmPosition);
    uploadLayers(*out.normal, maps.rsmNormal);
    uploadLayers(*out.flux, maps.rsmFlux);
  }
}

void Pipeline::renderGBuffer() {
  if (!raster_.hostPasses.count(kGBufferPass)) return gbufferPass_->render(*scene_, camera_, extras_);
  const GBuffer& g = gbufferPass_->gbuffer();
  const HostGBufferTargets out{.position = &hostReadback_.written(g.position),
                               .normal = &hostReadback_.written(g.normal),
                               .albedo = &hostReadback_.written(g.albedo),
                               .emission = g.emissive ? &hostReadback_.written(g.emission) : nullptr};
  raster_.host->renderGBuffer(camera_, gbufferPass_->clipFromWorld(camera_), out);
  if (uploadRasterImages_)
    for (const auto& [image, texture] : {std::pair{out.position, &g.position}, {out.normal, &g.normal},
                                         {out.albedo, &g.albedo}, {out.emission, &g.emission}})
      if (image) uploadLayers(*image, *texture);
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
          {"albedo", toImage(hostReadback_.image(g.albedo), 3)},
          {"normal", toImage(hostReadback_.image(g.normal), 3)},
          {"depth", toImage(hostReadback_.image(g.normal), 1, 3)}};
}

const LightMaps& Pipeline::lightMaps() const { return lightMapsPass_->lightMaps(); }

const GBuffer& Pipeline::gbuffer() const { return gbufferPass_->gbuffer(); }

nlohmann::json Pipeline::computeReport() const {
  nlohmann::json report = {{"backend", backendName(backend_)},
                           {"raster", raster_.record},
                           {"shadows", settings_.shadow.rays ? "rays" : "map"},
                           {"direct", direct_->onCpu() ? "cpu" : "gl"}};
  for (const char* pass : {kShadowMapPass, kRsmPass, kGBufferPass})
    report["raster"]["passes"][pass] = raster_.hostPasses.count(pass) ? "embree" : "gl";
  if (raster_.host) report["raster"]["embree"] = raster_.host->report();
  report["raster"]["uploaded_to_gl"] = uploadRasterImages_;
  report.update(method_->computeReport());
  return report;
}

nlohmann::json Pipeline::workReport(bool glKernels) const {
  const LightMaps& maps = lightMapsPass_->lightMaps();
  const double pixels = double(settings_.width) * settings_.height;
  nlohmann::json report = nlohmann::json::object();
  const double shadowTexels = double(maps.views) * maps.shadowResolution * maps.shadowResolution;
  if (renders(raster::kShadowMaps.name)) report["shadow_maps"] = {workCountJson({"texel", shadowTexels})};
  if (renders(raster::kReflectiveShadowMaps.name))
    report["rsm"] = {workCountJson({"texel", double(maps.views) * maps.rsmResolution * maps.rsmResolution})};
  report["gbuffer"] = {workCountJson({"pixel", pixels})};
  report["direct"] = {workCountJson(direct_->work(pixels, maps.lightCount, glKernels))};
  report.update(method_->workReport(glKernels));
  return report;
}

nlohmann::json Pipeline::memoryReport() const {
  nlohmann::json bytes = {
      {"scene", scene_->memoryBytes()},
      {"gbuffer", gbufferPass_->gbuffer().memoryBytes()},
      {"light_maps", lightMapsPass_->lightMaps().memoryBytes()},
      {"output_images", directImage_.memoryBytes() + indirectImage_.memoryBytes()}};
  if (raster_.host) bytes["raster_scene"] = raster_.host->memoryBytes();
  const nlohmann::json method = method_->memoryReport();  // kept: items() refers into it
  for (const auto& [name, value] : method.items())
    bytes[name] = bytes.value(name, std::size_t(0)) + value.get<std::size_t>();
  std::size_t total = 0;
  for (const auto& [name, value] : bytes.items()) total += value.get<std::size_t>();
  bytes["total"] = total;
  return bytes;
}

std::string Pipeline::derivativeRefusal(const std::string& key) const {
  return method_->derivativeRefusal(key);
}

Pipeline::FrameDerivatives Pipeline::renderDerivatives(const std::vector<std::string>& seeds) {
  if (seeds.size() > std::size_t(kDualSlots))
    throw Error("derivatives: " + std::to_string(seeds.size()) + " parameters at once, at most " +
                std::to_string(kDualSlots));
  for (const std::string& seed : seeds)
    if (const std::string why = derivativeRefusal(seed); !why.empty())
      throw Error("derivatives of '" + seed + "': " + why);
  return method_->renderDerivatives(seeds, [this] { renderFrame(); });
}

}  // namespace lpvlab
