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
#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/strategy.h"
#include "variants/injection/rsm_vpl_cpu.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {

namespace kernel {
#include "shaders/injection/rsm_vpl_interface.glsl"
}

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

  // Per RSM texel (a VPL), per level: 3 texel fetches (16 B each); the lobe (N coefficients,
  // about a multiply-add each) and 3N products; the cell from the shifted position (about 10);
  // with the normal grid 4 more sums. GL adds the products atomically (read and write, 8 B
  // each); the CPU writes and reads the texel's cell and its place in the sort by cell
  // (4 + 8 B, each twice) and sums in registers, each cell's total stored once (not counted).
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    const double n = shape.coefficients;
    const double normals = requirements.has(kNormalGrid) ? 4.0 : 0.0;
    const double bytes = runsOnCpu(requirements) ? 3 * 16 + 2 * (4 + 8) : 3 * 16 + 8 * (3 * n + normals);
    return {{"VPL", shape.rsmTexels * shape.levels, 4 * n + 10 + normals, bytes}};
  }

  void prepare(const StrategySetup& setup) override {
    coefficients_ = shared::shCoefficientCount(setup.requirements.shOrder);
    onCpu_ = runsOnCpu(setup.requirements);
    if (onCpu_) return;
    program_ = setup.shaders.compute(
        "injection/rsm_vpl.comp",
        {SpecConstant::i(0, shared::shCoefficientCount(setup.requirements.shOrder)),
         SpecConstant::b(1, setup.requirements.has(kNormalGrid))});
  }

  void inject(Frame& frame) override {
    if (onCpu_) return injectOnCpu(frame);
    using namespace kernel;
    const LightMaps& maps = frame.lightMaps;
    const GridGeometry& grid = frame.lightGrid.geometry;
    program_.use();
    glBindTextureUnit(UNIT_RSM_POSITION, maps.rsmPosition.id());
    glBindTextureUnit(UNIT_RSM_NORMAL, maps.rsmNormal.id());
    glBindTextureUnit(UNIT_RSM_FLUX, maps.rsmFlux.id());
    frame.lightGrid.current.bindStorage(BUFFER_GRID);
    if (const NormalGrid* normals = frame.find(kNormalGrid)) normals->normals.bindStorage(BUFFER_NORMALS);
    glUniform3fv(LOCATION_GRID_ORIGIN, 1, &grid.origin[0]);
    glUniform1f(LOCATION_CELL_SIZE, grid.cellSize);
    glUniform3iv(LOCATION_RESOLUTION, 1, &grid.resolution[0]);
    glUniform1f(LOCATION_SHIFT_CELLS, shiftCells_);
    glUniform1i(LOCATION_RSM_RESOLUTION, maps.rsmResolution);
    dispatchCovering({maps.rsmResolution, maps.rsmResolution, maps.views},
                     {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_SHADER_STORAGE_BARRIER_BIT);
  }

  std::size_t memoryBytes() const override {
    return hostNormals_.size() * sizeof(float);
  }

private:
  void injectOnCpu(Frame& frame) {
    if (!frame.host) throw Error("[injection] rsm_vpl (CPU): the frame has no host images");
    const LightMaps& maps = frame.lightMaps;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // the RSMs, before reading them back
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
  Program program_;
  bool onCpu_ = false;
  int coefficients_ = 4;
  std::vector<float> hostNormals_;  // on the CPU backend
};

LPVLAB_REGISTER(InjectionStrategy, "rsm_vpl",
                "RSM texels as Lambertian VPLs, shifted along their normals (thesis 4.3)",
                RsmVplInjection);

}  // namespace
}  // namespace lpvlab
