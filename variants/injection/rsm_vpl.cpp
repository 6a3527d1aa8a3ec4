// Injection "rsm_vpl": every reflective-shadow-map texel becomes a virtual point light in the
// light grid (thesis 4.3, eq. 4.1-4.3; kernel shaders/injection/rsm_vpl.comp), at any SH order.
// It produces the normal grid: when a strategy consumes it (directed propagation), the VPLs'
// normals go there too. On the CPU backend it runs rsm_vpl_cpu.h (the same shared VPL
// functions, shaders/injection/vpl.glsl, without atomics): the RSM is read back once per frame,
// and the VPLs are added to the light grid's host side (dual_buffer.h); the normal grid is read
// from GL and written back.
//
// | parameter | type  | default | meaning                                                       |
// |-----------|-------|---------|---------------------------------------------------------------|
// | shift     | float | 1.0     | move each VPL this many cells along its normal before         |
// |           |       |         | choosing its cell (the thesis found half a cell too little)   |

#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/strategy.h"
#include "variants/injection/rsm_vpl_cpu.h"
#include "variants/injection/rsm_vpl_gl.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {

class RsmVplInjection final : public InjectionStrategy {
public:
  explicit RsmVplInjection(Params& params)
      : shiftCells_(params.get<float>("shift", 1.0f, {.min = -4.0f, .max = 4.0f})) {}

  int maxShOrder() const override { return 3; }
  void declare(ResourceUses& uses) const override {
    uses.consumes(raster::kReflectiveShadowMaps, "its VPLs");
    uses.produces(kNormalGrid);
  }
  std::string cpuRefusal(const Requirements&) const override { return {}; }

  // Per RSM texel (a VPL), per level: rsm_vpl_gl.h's count on GL; the CPU does the same
  // arithmetic, and writes and reads the texel's cell and its place in the sort by cell (4 + 8 B,
  // each twice) and sums in registers, each cell's total stored once (not counted).
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    KernelWork w = rsmVplGlWork(shape.coefficients, requirements.has(kNormalGrid));
    if (runsOnCpu(requirements)) w.bytes = 3 * 16 + 2 * (4 + 8);
    return {{"VPL", shape.rsmTexels * shape.levels, w.multiplyAdds, w.bytes}};
  }

  void prepare(const StrategySetup& setup) override {
    coefficients_ = shared::shCoefficientCount(setup.requirements.shOrder);
    onCpu_ = runsOnCpu(setup.requirements);
    if (onCpu_) return;
    gl_ = RsmVplGlKernel(setup.shaders, coefficients_, setup.requirements.has(kNormalGrid),
                         shiftCells_);
  }

  void inject(Frame& frame) override {
    if (onCpu_) return injectOnCpu(frame);
    const LightMaps& maps = frame.lightMaps;
    const NormalGrid* normals = frame.find(kNormalGrid);
    gl_.inject({.position = maps.rsmPosition.id(),
                .normal = maps.rsmNormal.id(),
                .flux = maps.rsmFlux.id(),
                .resolution = maps.rsmResolution,
                .views = maps.views},
               frame.lightGrid.geometry, frame.lightGrid.current,
               normals ? &normals->normals : nullptr);
  }

  std::size_t memoryBytes() const override {
    return hostNormals_.size() * sizeof(float);
  }

private:
  void injectOnCpu(Frame& frame) {
    if (!frame.host) throw Error("[injection] rsm_vpl (CPU): the frame has no host images");
    const LightMaps& maps = frame.lightMaps;
    gl::barrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // the RSMs, before reading them back
    LightGrid& grid = frame.lightGrid;
    std::vector<float>& light = grid.current.host();  // added to on the host
    NormalGrid* normals = frame.find(kNormalGrid);
    if (normals) downloadFloats(normals->normals, std::size_t(grid.geometry.cellCount()) * 4, hostNormals_);
    injectRsmVplsCpu({.position = &frame.host->image(maps.rsmPosition),
                      .normal = &frame.host->image(maps.rsmNormal),
                      .flux = &frame.host->image(maps.rsmFlux)},
                     grid.geometry, coefficients_, shiftCells_, light.data(),
                     normals ? hostNormals_.data() : nullptr);
    if (normals) uploadFloats(hostNormals_, normals->normals);
  }

  float shiftCells_;
  RsmVplGlKernel gl_;  // on GL
  bool onCpu_ = false;
  int coefficients_ = 4;
  std::vector<float> hostNormals_;  // on the CPU backend
};

LPVLAB_REGISTER(InjectionStrategy, "rsm_vpl",
                "RSM texels as Lambertian VPLs, shifted along their normals (thesis 4.3)",
                RsmVplInjection);

}  // namespace
}  // namespace lpvlab
