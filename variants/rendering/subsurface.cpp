// Rendering "subsurface": the subsurface-scattering LPV (thesis 5.4, 6.9.4). What it does, its
// parameters and its units: subsurface.h; the mathematics: docs/variants/subsurface.md#subsurface.

#include "variants/rendering/subsurface.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <toml++/toml.h>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/gl/dispatch.h"
#include "framework/math/bounds.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "framework/scene/scene.h"
#include "variants/rendering/subsurface_cpu.h"

namespace lpvlab {

namespace translucency_kernel {  // the RSM's and the mask's material buffer
#include "shaders/subsurface/translucency_interface.glsl"
}
namespace rsm_kernel {
#include "shaders/common/light_records_interface.glsl"
#include "shaders/subsurface/rsm_interface.glsl"
}
namespace propagate_kernel {
#include "shaders/subsurface/propagate_interface.glsl"
}
namespace render_kernel {
#include "shaders/subsurface/render_interface.glsl"
}
using scene_vertex::LOCATION_CLIP_FROM_WORLD;

namespace {

// The RSM injection as an experiment would create it, with shift 0: the thesis injects the
// SSLPV's VPLs at their surface (step 2), and this RSM already stores the inward normals.
std::unique_ptr<InjectionStrategy> unshiftedRsmInjection() {
  toml::table table;
  table.insert("shift", 0.0);
  Params params(table, "rendering \"subsurface\"", "injection");
  std::unique_ptr<InjectionStrategy> injection =
      Registry<InjectionStrategy>::instance().create(params, "rsm_vpl");
  params.finish();
  return injection;
}

std::string materialList(const std::vector<const Material*>& materials) {
  std::string names;
  for (const Material* m : materials)
    names += (names.empty() ? "'" : ", '") + m->name + "' (" + std::to_string(m->extinction) + "/m)";
  return names;
}

}  // namespace

SubsurfaceRendering::SubsurfaceRendering(Params& params)
    : resolution_(params.get<int>("resolution", 16, {.min = 2, .max = 256})),
      iterations_(params.get<int>("iterations", 16, {.min = 0, .max = 4096})),
      rsmResolution_(params.get<int>("rsm_resolution", 128, {.min = 1, .max = 4096})),
      marginCells_(params.get<float>("margin", 1.0f, {.min = 0.0f, .max = 16.0f})) {}

SubsurfaceRendering::~SubsurfaceRendering() = default;

float SubsurfaceRendering::stepAttenuation(float extinction, float cellSize) {
  return float(std::exp(-double(extinction) * double(cellSize)));
}

void SubsurfaceRendering::prepare(const StrategySetup& setup) {
  ShaderCompiler& shaders = setup.shaders;
  shOrder_ = setup.requirements.shOrder;
  backend_ = setup.requirements.backend;
  onCpu_ = runsOnCpu(setup.requirements);
  const int coefficients = shared::shCoefficientCount(shOrder_);
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  rsmProgram_ = shaders.graphics("raster/scene.vert", "subsurface/rsm.frag");
  maskProgram_ = shaders.graphics("raster/scene.vert", "subsurface/mask.frag");
  propagateProgram_ = shaders.compute(
      "subsurface/propagate.comp",
      {SpecConstant::f(0, float(angles.farFace)), SpecConstant::f(1, float(angles.sideFace)),
       SpecConstant::i(2, coefficients)});
  renderProgram_ = shaders.compute("subsurface/render.comp", {SpecConstant::i(0, coefficients)});
  // The SSLPV has no normal grid, GV or cascade of its own, whatever the main LPV has.
  Requirements own;
  own.shOrder = shOrder_;
  own.backend = backend_;  // its injection runs where the run's strategies do
  injection_ = unshiftedRsmInjection();
  injection_->prepare({.shaders = shaders, .grid = setup.grid, .requirements = own});
  if (setup.scene && setup.lightMaps) setUp(*setup.scene, *setup.lightMaps, setup.imageSize);
}

void SubsurfaceRendering::allocateGrid(const GridGeometry& geometry, float extinction) {
  grid_ = LightGrid(geometry, shOrder_);
  attenuation_ = stepAttenuation(extinction, geometry.cellSize);
  if (onCpu_) {
    const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
    cpu_ = StandardCpuFrame(shOrder_, attenuation_ * angles.farFace, attenuation_ * angles.sideFace,
                            grid_.floatsPerGrid());
  } else {
    scratch_ = DualBuffer(grid_.bytesPerGrid(), "subsurface LPV (propagation scratch)");
  }
}

bool SubsurfaceRendering::setUp(const SceneGpu& scene, const LightMaps& lightMaps,
                                glm::ivec2 imageSize) {
  const std::vector<Material>& materials = scene.materials();
  std::vector<const Material*> translucent;
  Bounds bounds;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const Bounds& own = scene.materialBounds(int(m));
    if (!materials[m].translucent() || own.empty()) continue;
    translucent.push_back(&materials[m]);
    bounds.extend(own.min);
    bounds.extend(own.max);
  }
  active_ = !translucent.empty();
  if (!active_) return false;
  const auto differs = [&](const Material* m) { return m->extinction != translucent[0]->extinction; };
  if (std::any_of(translucent.begin(), translucent.end(), differs))
    throw Error("rendering \"subsurface\": the translucent materials " + materialList(translucent) +
                " differ in extinction; one subsurface LPV has one attenuation per step, so give "
                "them one extinction in [[materials]]");
  allocateGrid(GridGeometry::fitted(bounds, resolution_, marginCells_), translucent[0]->extinction);

  std::vector<glm::vec4> records;
  for (const Material& m : materials) records.emplace_back(m.transmittance, m.extinction);
  translucency_ = gl::Buffer(records.size() * sizeof(glm::vec4), "subsurface translucency",
                             records.data());

  // The RSM: one layer per light view of the main light maps, with their view matrices.
  const int views = lightMaps.views, r = rsmResolution_;
  rsmClipFromWorld_.clear();
  for (const GpuView& view : lightMaps.records.views) rsmClipFromWorld_.push_back(view.clipFromWorld);
  rsm_ = LightMaps();
  rsm_.views = views;
  rsm_.rsmResolution = r;
  rsm_.lightCount = lightMaps.lightCount;
  rsmFramebuffers_ = allocateRsm(rsm_, r, views, "subsurface rsm");

  const int w = imageSize.x, h = imageSize.y;
  mask_ = gl::Texture(GL_TEXTURE_2D, GL_R8, w, h, 1, "subsurface mask");
  maskDepth_ = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, w, h, 1, "subsurface mask depth");
  maskFramebuffer_.emplace();
  maskFramebuffer_->attach(GL_COLOR_ATTACHMENT0, mask_);
  maskFramebuffer_->attach(GL_DEPTH_ATTACHMENT, maskDepth_);
  maskFramebuffer_->checkComplete("subsurface mask");
  checkGl("subsurface LPV setup");
  return true;
}

void SubsurfaceRendering::renderRsm(const Frame& frame) {
  using namespace rsm_kernel;
  rsmProgram_.use();
  frame.lightMaps.lightRecords.bindStorage(BUFFER_LIGHTS);
  frame.lightMaps.viewRecords.bindStorage(BUFFER_VIEWS);
  translucency_.bindStorage(translucency_kernel::BUFFER_TRANSLUCENCY);
  glUniform1i(LOCATION_RESOLUTION, rsm_.rsmResolution);
  for (int layer = 0; layer < rsm_.views; ++layer) {
    beginRaster(rsmFramebuffers_[std::size_t(layer)], rsm_.rsmResolution, rsm_.rsmResolution, 3);
    glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE,
                       &rsmClipFromWorld_[std::size_t(layer)][0][0]);
    glUniform1i(LOCATION_VIEW_INDEX, layer);
    frame.scene->draw();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void SubsurfaceRendering::inject(const Frame& frame) {
  grid_.current.zero();
  Frame own{.scene = frame.scene,
            .camera = frame.camera,
            .gbuffer = frame.gbuffer,
            .lightMaps = rsm_,
            .lightGrid = grid_,
            .indirect = frame.indirect,
            .host = frame.host};
  injection_->inject(own);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  // The accumulated light starts as the injected light, as in the main LPV (on the side the
  // injection wrote).
  grid_.accumulated.copyFrom(grid_.current);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void SubsurfaceRendering::propagate() {
  if (onCpu_) return cpu_.propagate(grid_, {.count = iterations_});
  using namespace propagate_kernel;
  propagateProgram_.use();
  glUniform3iv(LOCATION_RESOLUTION, 1, &grid_.geometry.resolution[0]);
  glUniform1f(LOCATION_ATTENUATION, attenuation_);
  grid_.accumulated.bindStorage(BUFFER_ACCUMULATED);
  for (int i = 0; i < iterations_; ++i) {
    grid_.current.bindStorage(BUFFER_SOURCE);
    scratch_.bindStorage(BUFFER_TARGET);
    dispatchCovering(grid_.geometry.resolution, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                     GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(grid_.current, scratch_);
  }
}

void SubsurfaceRendering::shade(Frame& frame) {
  if (!frame.camera) throw Error("rendering \"subsurface\": the frame has no camera");
  const int w = frame.gbuffer.width, h = frame.gbuffer.height;
  beginRaster(*maskFramebuffer_, w, h, 1);
  maskProgram_.use();
  const glm::mat4 clip = cameraClipFromWorld(*frame.camera, w, h);
  glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clip[0][0]);
  translucency_.bindStorage(translucency_kernel::BUFFER_TRANSLUCENCY);
  frame.scene->draw();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  if (onCpu_) {
    if (!frame.host) throw Error("rendering \"subsurface\" (CPU): the frame has no host images");
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // the mask, before reading it back
    addSubsurfaceLightCpu({.position = &frame.host->image(frame.gbuffer.position),
                           .normal = &frame.host->image(frame.gbuffer.normal),
                           .mask = &frame.host->image(mask_),
                           .accumulated = grid_.accumulated.hostRead().data(),
                           .geometry = grid_.geometry,
                           .coefficients = shared::shCoefficientCount(shOrder_)},
                          frame.indirect.host());
    return;
  }
  using namespace render_kernel;
  const GridGeometry& g = grid_.geometry;
  renderProgram_.use();
  glBindTextureUnit(UNIT_G_POSITION, frame.gbuffer.position.id());
  glBindTextureUnit(UNIT_G_NORMAL, frame.gbuffer.normal.id());
  glBindTextureUnit(UNIT_TRANSLUCENT_MASK, mask_.id());
  grid_.accumulated.bindStorage(BUFFER_ACCUMULATED);
  glBindImageTexture(IMAGE_INDIRECT, frame.indirect.texture().id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glUniform3fv(LOCATION_GRID_ORIGIN, 1, &g.origin[0]);
  glUniform1f(LOCATION_CELL_SIZE, g.cellSize);
  glUniform3iv(LOCATION_RESOLUTION, 1, &g.resolution[0]);
  dispatchCovering({w, h, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_ALL_BARRIER_BITS);
}

void SubsurfaceRendering::render(Frame& frame) {
  if (!active_) return;  // no translucent surface, or prepare() had no scene
  renderRsm(frame);
  inject(frame);
  propagate();
  shade(frame);
}

std::size_t SubsurfaceRendering::memoryBytes() const {
  if (!active_) return 0;
  return grid_.memoryBytes() + scratch_.size() + cpu_.memoryBytes() + translucency_.size() +
         rsm_.memoryBytes() + mask_.bytes() + maskDepth_.bytes();
}

LPVLAB_REGISTER(RenderingStrategy, "subsurface",
                "subsurface-scattering LPV: light transmitted into translucent materials, "
                "propagated with attenuation, read at their surfaces (thesis 5.4); for "
                "[[rendering.also]]",
                SubsurfaceRendering);

}  // namespace lpvlab
