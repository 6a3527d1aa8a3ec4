#include "framework/pipeline/pipeline.h"

#include <chrono>

#include "framework/core/error.h"
#include "framework/math/shared.h"

namespace lpvlab {

namespace {

// A float texture's level 0, flipped to top row first, keeping `channels` of its RGBA.
Image readTexture(const gl::Texture& texture, int channels, int firstChannel = 0) {
  const int w = texture.width(), h = texture.height();
  std::vector<float> rgba(std::size_t(w) * h * 4);
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
                    rgba.data());
  Image image(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        image.at(x, h - 1 - y, c) = rgba[(std::size_t(y) * w + x) * 4 + firstChannel + c];
  return image;
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
    : settings_(settings), camera_(camera), strategies_(std::move(strategies)) {
  if (scene.lights.empty())
    throw Error(scene.source + ": the scene has no light the LPV pipeline can use (point, spot or "
                "directional; emissive surfaces are shown but light nothing in LPV runs); add one "
                "under [[lights]] in the experiment");
  requirements_ = resolveRequirements(strategies_, settings.shOrder, settings.skyRadiance);

  scene_ = std::make_unique<SceneGpu>(scene);
  gbufferPass_ = std::make_unique<GBufferPass>(shaders, settings.width, settings.height);
  lightMapsPass_ = std::make_unique<LightMapsPass>(
      shaders, buildLightViews(scene.lights, scene.bounds()), settings.rsmResolution,
      settings.shadowResolution);
  direct_ = std::make_unique<DirectLighting>(shaders, settings.shadow);
  lightGrid_ = LightGrid(settings.grid, requirements_.shOrder);
  if (requirements_.geometryVolume)
    geometryVolume_ = std::make_unique<GeometryVolume>(settings.grid, requirements_.surfaceAlbedo);
  if (requirements_.normalGrid) normalGrid_ = std::make_unique<NormalGrid>(settings.grid);
  directImage_ = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, settings.width, settings.height, 1, "direct");
  indirectImage_ =
      gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, settings.width, settings.height, 1, "indirect");
  for (const auto& [table, strategy] : strategies_.all())
    strategy->prepare(shaders, settings.grid, requirements_);
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
}

Frame Pipeline::frame() {
  return Frame{.scene = scene_.get(),
               .camera = &camera_,
               .gbuffer = gbufferPass_->gbuffer(),
               .lightMaps = lightMapsPass_->lightMaps(),
               .lightGrid = lightGrid_,
               .indirect = indirectImage_,
               .geometryVolume = geometryVolume_.get(),
               .normalGrid = normalGrid_.get(),
               .skyRadiance = settings_.skyRadiance};
}

void Pipeline::clearGrids() {
  lightGrid_.current.zero();
  if (geometryVolume_) geometryVolume_->clear();
  if (normalGrid_) normalGrid_->clear();
}

void Pipeline::injectAll(Frame& frame) {
  for (const auto& injection : strategies_.injection) injection->inject(frame);
}

FrameTimes Pipeline::renderFrame() {
  FrameTimes times;
  Frame frame = this->frame();
  stage("shadow_maps", times, [&] { lightMapsPass_->renderShadowMaps(*scene_); });
  stage("rsm", times, [&] { lightMapsPass_->renderRsms(*scene_); });
  stage("gbuffer", times, [&] { gbufferPass_->render(*scene_, camera_); });
  stage("direct", times, [&] {
    direct_->render(gbufferPass_->gbuffer(), lightMapsPass_->lightMaps(), directImage_);
  });
  stage("clear", times, [&] { clearGrids(); });
  stage("occlusion", times, [&] { strategies_.occlusion->inject(frame); });
  stage("injection", times, [&] {
    injectAll(frame);
    // The accumulated light starts as the injected light (thesis 6.9.1).
    glCopyNamedBufferSubData(lightGrid_.current.id(), lightGrid_.accumulated.id(), 0, 0,
                             GLsizeiptr(lightGrid_.bytesPerGrid()));
  });
  stage("propagation", times, [&] { strategies_.propagation->propagate(frame); });
  stage("indirect", times, [&] { strategies_.rendering->render(frame); });
  times.gpuMs = gpuTimer_.collectMs();
  checkGl("frame");
  return times;
}

std::vector<NamedImage> Pipeline::readOutputs() const {
  const GBuffer& g = gbufferPass_->gbuffer();
  Image direct = readTexture(directImage_, 3);
  Image indirect = readTexture(indirectImage_, 3);
  Image combined = direct;
  for (std::size_t i = 0; i < combined.pixels.size(); ++i) combined.pixels[i] += indirect.pixels[i];
  return {{"direct", std::move(direct)},
          {"indirect", std::move(indirect)},
          {"combined", std::move(combined)},
          {"albedo", readTexture(g.albedo, 3)},
          {"normal", readTexture(g.normal, 3)},
          {"depth", readTexture(g.normal, 1, 3)}};
}

std::vector<float> Pipeline::readGrid(bool accumulated) const {
  std::vector<float> data(lightGrid_.floatsPerGrid());
  (accumulated ? lightGrid_.accumulated : lightGrid_.current)
      .download(data.data(), data.size() * sizeof(float));
  return data;
}

InjectionBalance Pipeline::measureInjection() {
  Frame frame = this->frame();
  clearGrids();
  strategies_.occlusion->inject(frame);
  InjectionBalance balance;
  const auto all = strategies_.all();
  for (std::size_t i = 0; i < strategies_.injection.size(); ++i) {
    strategies_.injection[i]->inject(frame);
    const double total =
        gridFlux(readGrid(false), lightGrid_.geometry.cellCount(), lightGrid_.coefficients);
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

nlohmann::json Pipeline::memoryReport() const {
  nlohmann::json bytes = {
      {"scene", scene_->memoryBytes()},
      {"gbuffer", gbufferPass_->gbuffer().memoryBytes()},
      {"light_maps", lightMapsPass_->lightMaps().memoryBytes()},
      {"light_grid", lightGrid_.memoryBytes()},
      {"geometry_volume", geometryVolume_ ? geometryVolume_->memoryBytes() : 0},
      {"normal_grid", normalGrid_ ? normalGrid_->memoryBytes() : 0},
      {"output_images", directImage_.bytes() + indirectImage_.bytes()}};
  for (const auto& [table, strategy] : strategies_.all())
    bytes[table] = bytes.value(table, std::size_t(0)) + strategy->memoryBytes();
  std::size_t total = 0;
  for (const auto& [name, value] : bytes.items()) total += value.get<std::size_t>();
  bytes["total"] = total;
  return bytes;
}

}  // namespace lpvlab
