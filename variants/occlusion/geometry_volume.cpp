// Occlusion "geometry_volume": fills the geometry volume (thesis 4.1, 4.3; eq. 4.4) with the
// blocking potential of the surfaces the light views' RSMs and the camera's G-buffer see, so that
// propagation can attenuate light passing through surfaces (thesis 4.4, alg. 6.2 lines 11-14).
// Every covered RSM texel or G-buffer pixel is a surfel of area A_s, its footprint on the surface
// (shaders/occlusion/surfel_area.glsl), with the normal facing its viewer; it adds
// A_s / s^2 * cosLobe(-n) to the GV cell containing it (shaders/occlusion/gv_surfel.glsl). With
// both sources, each fills a GV of its own and the two are merged "by the larger coefficients":
// per GV cell the whole cell of the source with the larger c0 (shaders/occlusion/gv_merge.comp).
// It produces the GV and the surfaces' albedo (resources kGeometryVolume, kSurfaceAlbedo). When a
// strategy consumes the albedo (multiple bounces),
// each surfel also adds its albedo, weighted by its A_s / s^2, to the GV's albedo: a camera
// surfel the G-buffer's, an RSM surfel its reflected flux over the flux arriving at it. Albedo is
// a weighted mean, not a sum, so both sources add to the one albedo buffer without merging.
// docs/variants/geometry_volume.md#geometry_volume has the mathematics. On the CPU backend the same surfels are
// summed per cell without atomics (geometry_volume_cpu.h).
// With `history`, the GV of the frames before is kept and merged into each frame's by the same
// rule, with its albedo: "for static scenes the GV need not be built anew each frame; the GV of
// previous frames can be used and the new RSMs' information added" (thesis 4.3). Surfaces the
// camera or a light saw once keep blocking after they leave the view. A level's history starts
// anew when its GV moves (a cascade level following the camera to other cells) or the scene's
// geometry moves (Frame::geometryVersion); lights may move, since the GV holds only surfaces.
//
// | parameter            | type     | default             | meaning                              |
// |----------------------|----------|---------------------|--------------------------------------|
// | sources              | [string] | ["light", "camera"] | whose surfels fill the GV: "light"   |
// |                      |          |                     | (every light view's RSM), "camera"   |
// |                      |          |                     | (the G-buffer); at least one         |
// | skip_first_iteration | bool     | true                | propagation step 0 ignores the GV:   |
// |                      |          |                     | a VPL's light leaves its cell past   |
// |                      |          |                     | its own surface's surfels            |
// | blocking_scale       | float    | 1.0                 | every surfel's blocking potential    |
// |                      |          |                     | times this (0..100), a constant to   |
// |                      |          |                     | fit (docs/fitting.md): the GV is     |
// |                      |          |                     | linear in it; the transmittance      |
// |                      |          |                     | clamp(1 - B, 0, 1) only where B < 1  |
// | history              | bool     | false               | merge in the GV of the frames before |
// |                      |          |                     | while the geometry and the GV's      |
// |                      |          |                     | placement stay put (thesis 4.3)      |

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/strategy.h"
#include "framework/scene/scene.h"
#include "variants/occlusion/geometry_volume_cpu.h"
#include "variants/occlusion/geometry_volume_gl.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {

class GeometryVolumeOcclusion final : public OcclusionStrategy {
public:
  explicit GeometryVolumeOcclusion(Params& params)
      : skipFirstIteration_(params.get<bool>("skip_first_iteration", true)),
        blockingScale_(params.get<float>("blocking_scale", 1.0f, {.min = 0.0f, .max = 100.0f})),
        keepHistory_(params.get<bool>("history", false)) {
    const auto sources = params.get<std::vector<std::string>>("sources", {"light", "camera"});
    for (const std::string& source : sources) {
      if (source != "light" && source != "camera")
        throw Error(params.where("sources") + ": unknown source '" + source +
                    "' (choices: \"light\", \"camera\")");
    }
    fromLight_ = std::count(sources.begin(), sources.end(), "light") > 0;
    fromCamera_ = std::count(sources.begin(), sources.end(), "camera") > 0;
    if (!fromLight_ && !fromCamera_)
      throw Error(params.where("sources") + ": needs at least one of \"light\", \"camera\"");
    if (sources.size() != std::size_t(fromLight_) + std::size_t(fromCamera_))
      throw Error(params.where("sources") + ": a source is listed twice");
  }

  void declare(ResourceUses& uses) const override {
    if (fromLight_) uses.consumes(raster::kReflectiveShadowMaps, "sources = [\"light\"]");
    uses.produces(kGeometryVolume, skipFirstIteration_ ? 1 : 0);
    uses.produces(kSurfaceAlbedo);
  }
  int maxShOrder() const override { return 3; }  // the GV is order 1 whatever the light grid's
  bool keepsStateBetweenFrames() const override { return keepHistory_; }
  std::string cpuRefusal(const Requirements&) const override { return {}; }

  // Per surfel (a covered G-buffer pixel or RSM texel): geometry_volume_gl.h's count on GL; the
  // CPU does the same arithmetic, and writes and reads the surfel's cell and its place in the sort
  // by cell (4 + 8 B, each twice), summing each cell in registers.
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    if (!requirements.has(kGeometryVolume)) return {};
    KernelWork w = gvSurfelGlWork(requirements.has(kSurfaceAlbedo));
    if (runsOnCpu(requirements)) w.bytes = 3 * 16 + 2 * (4 + 8);
    const double surfels =
        ((fromLight_ ? shape.rsmTexels : 0.0) + (fromCamera_ ? shape.pixels : 0.0)) * shape.levels;
    std::vector<WorkCount> counts = {{"surfel", surfels, w.multiplyAdds, w.bytes}};
    // The history's merge and copy: per GV cell (about a light-grid cell), the frame's and the
    // history's 4 coefficients (and albedo sums) read, one compare, the kept cell written to both
    // (4 B each).
    if (keepHistory_) {
      const double floats = requirements.has(kSurfaceAlbedo) ? 8.0 : 4.0;
      counts.push_back({"history-cell", shape.cells * shape.levels, 1, 4 * floats * 4});
    }
    return counts;
  }

  void prepare(const StrategySetup& setup) override {
    ShaderCompiler& shaders = setup.shaders;
    const GridGeometry& grid = setup.grid;
    active_ = setup.requirements.has(kGeometryVolume);  // no propagation uses one: nothing to do
    withAlbedo_ = setup.requirements.has(kSurfaceAlbedo);
    if (!active_) return;
    onCpu_ = runsOnCpu(setup.requirements);
    if (keepHistory_) prepareHistories(setup);
    if (onCpu_) {  // the host copies, allocated once (each frame refills them)
      const std::size_t gvCells = std::size_t(GeometryVolume::placementFor(grid).cellCount());
      hostBlocking_.assign(gvCells * GeometryVolume::kCoefficients, 0.0f);
      if (fromCamera_ && fromLight_) hostLight_.assign(gvCells * GeometryVolume::kCoefficients, 0.0f);
      if (withAlbedo_) hostAlbedo_.assign(gvCells * 4, 0.0f);
      return;
    }
    gl_ = GeometryVolumeGlKernels(shaders, fromCamera_, fromLight_, withAlbedo_,
                                  keepHistory_ || (fromCamera_ && fromLight_));
    if (fromCamera_ && fromLight_) {
      const GridGeometry gv = GeometryVolume::placementFor(grid);
      lightScratch_ = gl::Buffer(std::size_t(gv.cellCount()) * GeometryVolume::kCoefficients *
                                     sizeof(float),
                                 "geometry volume (light views, before merging)");
    }
  }

  void inject(Frame& frame) override {
    if (!active_) return;
    if (onCpu_) return injectOnCpu(frame);
    GeometryVolume& gv = frame.get(kGeometryVolume);
    // The camera's surfels go straight into the GV; the lights' too when they are the only source.
    if (fromCamera_) injectCamera(frame, gv.blocking);
    if (fromLight_ && !fromCamera_) injectLightViews(frame, gv.blocking);
    if (fromLight_ && fromCamera_) {
      lightScratch_.zero();
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      injectLightViews(frame, lightScratch_);
      gl_.merge(gv.blocking, lightScratch_, nullptr, nullptr);
    }
    if (keepHistory_) {
      History& history = historyOf(frame);
      SurfaceAlbedo* albedo = withAlbedo_ ? &frame.get(kSurfaceAlbedo) : nullptr;
      if (history.valid)
        gl_.merge(gv.blocking, history.blocking, albedo ? &albedo->albedo : nullptr,
                  &history.albedo);
      history.blocking.copyFrom(gv.blocking);
      if (albedo) history.albedo.copyFrom(albedo->albedo);
      history.valid = true;
    }
  }

  // Derivatives with respect to blocking_scale. gvSurfelBlocking multiplies every surfel's
  // blocking by it and the merge of the camera's and the light's GVs picks per cell by comparing
  // them, which scaling both keeps: the GV is s GV_1, and its derivative is GV_1, the GV at scale
  // 1, which the same CPU kernel builds (on any backend: it reads the frame's host images).
  std::vector<std::string> differentiableParameters() const override { return {"blocking_scale"}; }
  void injectDual(DualFrame& dual) override {
    if (!active_ || !dual.frame.find(kGeometryVolume)) return;
    const Dual scale = dual.parameter("blocking_scale", blockingScale_);
    if (!scale.hasDerivatives()) return;  // a constant: the frame's GV
    std::vector<float> unit;
    buildOnCpu(dual.frame, 1.0f, unit, nullptr);
    dual.gvBlocking.resize(unit.size());
    for (std::size_t i = 0; i < unit.size(); ++i) dual.gvBlocking[i] = scale * double(unit[i]);
  }

  std::size_t memoryBytes() const override {
    std::size_t bytes =
        lightScratch_.size() +
        (hostBlocking_.size() + hostLight_.size() + hostAlbedo_.size()) * sizeof(float);
    for (const History& history : histories_)
      bytes += history.blocking.size() + history.albedo.size() +
               (history.hostBlocking.capacity() + history.hostAlbedo.capacity()) * sizeof(float);
    return bytes;
  }

private:
  // A level's GV of the frames before (with its albedo sums when they are used), on the side the
  // strategy runs; `valid` once a frame filled it, until the GV or the geometry moves.
  struct History {
    bool valid = false;
    GridGeometry placement;
    int geometryVersion = 0;
    gl::Buffer blocking, albedo;
    std::vector<float> hostBlocking, hostAlbedo;
  };

  void prepareHistories(const StrategySetup& setup) {
    const GridGeometry gv = GeometryVolume::placementFor(setup.grid);
    const std::size_t cells = std::size_t(gv.cellCount());
    histories_.resize(std::size_t(setup.requirements.cascadeLevels));
    if (onCpu_) return;  // the host vectors take each frame's size when first kept
    for (History& history : histories_) {
      history.blocking = gl::Buffer(cells * GeometryVolume::kCoefficients * sizeof(float),
                                    "geometry volume history");
      if (withAlbedo_) history.albedo = gl::Buffer(cells * 4 * sizeof(float), "GV albedo history");
    }
  }

  // The frame's level's history, emptied first when the GV or the geometry moved since it was kept.
  History& historyOf(const Frame& frame) {
    History& history = histories_.at(std::size_t(frame.level));
    const GridGeometry& placement = frame.get(kGeometryVolume).geometry;
    if (history.valid &&
        (placement != history.placement || frame.geometryVersion != history.geometryVersion))
      history.valid = false;
    history.placement = placement;
    history.geometryVersion = frame.geometryVersion;
    return history;
  }

  // Where this frame's surfels go on GL: `blocking`, and the frame's albedo sums when used.
  GvGlTarget glTarget(const Frame& frame, const gl::Buffer& blocking) const {
    return {.gv = frame.get(kGeometryVolume).geometry,
            .blockingScale = blockingScale_,
            .blocking = &blocking,
            .albedo = withAlbedo_ ? &frame.get(kSurfaceAlbedo).albedo : nullptr};
  }

  void injectCamera(Frame& frame, const gl::Buffer& target) {
    const GBuffer& g = frame.gbuffer;
    gl_.injectCamera({g.position.id(), g.normal.id(), g.albedo.id()}, g.width, g.height,
                     frame.camera->position, cameraTexelEdge(frame), glTarget(frame, target));
  }

  // The edge of a G-buffer pixel at unit depth.
  static float cameraTexelEdge(const Frame& frame) {
    return 2.0f * std::tan(0.5f * frame.camera->verticalFov) / float(frame.gbuffer.height);
  }

  // The same surfels on the CPU (geometry_volume_cpu.h), from the frame's host images, into host
  // copies of the GV (and its albedo) that replace the cleared GL buffers.
  void injectOnCpu(Frame& frame) {
    GeometryVolume& gv = frame.get(kGeometryVolume);
    SurfaceAlbedo* albedo = withAlbedo_ ? &frame.get(kSurfaceAlbedo) : nullptr;
    buildOnCpu(frame, blockingScale_, hostBlocking_, albedo ? &hostAlbedo_ : nullptr);
    if (keepHistory_) {
      History& history = historyOf(frame);
      if (history.valid)
        mergeGeometryVolumesCpu(hostBlocking_.data(), history.hostBlocking.data(),
                                gv.geometry.cellCount(), albedo ? hostAlbedo_.data() : nullptr,
                                albedo ? history.hostAlbedo.data() : nullptr);
      history.hostBlocking = hostBlocking_;
      if (albedo) history.hostAlbedo = hostAlbedo_;
      history.valid = true;
    }
    uploadFloats(hostBlocking_, gv.blocking);
    if (albedo) uploadFloats(hostAlbedo_, albedo->albedo);
  }

  // The GV of the frame's surfels at blocking scale `scale` into `blocking` (and `albedo`).
  void buildOnCpu(Frame& frame, float scale, std::vector<float>& blocking,
                  std::vector<float>* albedo) {
    if (!frame.host) throw Error("[occlusion] geometry_volume (CPU): the frame has no host images");
    gl::barrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // the G-buffer and RSMs, before reading them
    const GeometryVolume& gv = frame.get(kGeometryVolume);
    const std::size_t floats = std::size_t(gv.geometry.cellCount()) * GeometryVolume::kCoefficients;
    blocking.assign(floats, 0.0f);
    if (albedo) albedo->assign(std::size_t(gv.geometry.cellCount()) * 4, 0.0f);
    const GvTarget target{.gv = gv.geometry, .blockingScale = scale,
                          .blocking = blocking.data(),
                          .albedo = albedo ? albedo->data() : nullptr};
    if (fromCamera_) {
      const GBuffer& g = frame.gbuffer;
      addCameraSurfelsCpu({.position = &frame.host->image(g.position),
                           .normal = &frame.host->image(g.normal),
                           .albedo = albedo ? &frame.host->image(g.albedo) : nullptr},
                          frame.camera->position, cameraTexelEdge(frame), target);
    }
    if (fromLight_) {
      const LightMaps& maps = frame.lightMaps;
      const RsmImages rsm{.position = &frame.host->image(maps.rsmPosition),
                          .normal = &frame.host->image(maps.rsmNormal),
                          .flux = &frame.host->image(maps.rsmFlux)};
      if (fromCamera_) {  // a GV of its own, merged
        hostLight_.assign(floats, 0.0f);
        GvTarget lightTarget = target;
        lightTarget.blocking = hostLight_.data();
        addRsmSurfelsCpu(rsm, maps.records, lightTarget);
        mergeGeometryVolumesCpu(blocking.data(), hostLight_.data(), gv.geometry.cellCount());
      } else {
        addRsmSurfelsCpu(rsm, maps.records, target);
      }
    }
  }

  void injectLightViews(Frame& frame, const gl::Buffer& target) {
    const LightMaps& maps = frame.lightMaps;
    gl_.injectLightViews({maps.rsmPosition.id(), maps.rsmNormal.id(), maps.rsmFlux.id()},
                         maps.rsmResolution, maps.views, maps.lightRecords, maps.viewRecords,
                         glTarget(frame, target));
  }

  bool skipFirstIteration_;
  float blockingScale_;
  bool keepHistory_;
  std::vector<History> histories_;  // per cascade level, with `history`
  bool fromLight_ = false, fromCamera_ = false;
  bool active_ = false;
  bool withAlbedo_ = false;
  bool onCpu_ = false;
  GeometryVolumeGlKernels gl_;  // on GL
  gl::Buffer lightScratch_;
  std::vector<float> hostBlocking_, hostLight_, hostAlbedo_;  // on the CPU backend
};

LPVLAB_REGISTER(OcclusionStrategy, "geometry_volume",
                "blocking potential of the surfels the RSMs and the camera see, merged by the "
                "larger coefficients (thesis 4.3)",
                GeometryVolumeOcclusion);

}  // namespace
}  // namespace lpvlab
