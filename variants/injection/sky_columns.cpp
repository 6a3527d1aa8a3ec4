// Injection "sky_columns": light from a constant sky ([sky] radiance), column by column from the
// top of the grid down to the first surface (thesis 5.3 and 6.9.4; docs/variants/sky_columns.md#sky_columns).
// A top-down orthographic depth map of the scene over the grid's xz extent finds each texel's
// first surface; the flux pi L a through the texel's open top (a its area) is added to the cell
// above that surface as a downward Lambertian lobe (shaders/injection/sky_columns.glsl), at any
// SH order. Geometry above the grid's top and light entering through the grid's sides are
// ignored. Meant for [[injection.also]] beside the RSM injection. On the CPU backend the depth
// map is still rasterised by GL, read back, and injected by sky_columns_cpu.h (the same shared
// functions).
//
// | parameter       | type  | default | meaning                                                 |
// |-----------------|-------|---------|---------------------------------------------------------|
// | texels_per_cell | int   | 4       | depth-map texels per cell along x and z                 |
// | shift           | float | 1.0     | cells above the first surface at which the light is     |
// |                 |       |         | injected (1: the lowest free cell)                      |
// | fill            | string| "lowest_free_cell" | or "every_free_cell": the thesis's own     |
// |                 |       |         | implementation (6.9.4), the light in every cell from    |
// |                 |       |         | there up to the grid's top (not normalised)             |

#include <algorithm>
#include <optional>
#include <string>

#include "framework/core/error.h"
#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/raster_passes.h"
#include "variants/resources/sky_light.h"
#include "framework/pipeline/strategy.h"
#include "variants/injection/sky_columns_cpu.h"

namespace lpvlab {
namespace {

namespace kernel {
#include "shaders/injection/sky_columns_interface.glsl"
}

// Orthographic view straight down over the grid: clip x, y from world x, z across the grid's
// extent, depth 0 at the grid's top face and 1 at its bottom face (GL's default depth range maps
// clip z in [-1, 1] to [0, 1]).
glm::mat4 skyClipFromWorld(const GridGeometry& grid) {
  const glm::vec3 extent = grid.extent();
  const float top = grid.origin.y + extent.y;
  glm::mat4 m(0.0f);  // column-major: m[column][row]
  m[0][0] = 2.0f / extent.x;
  m[3][0] = -2.0f * grid.origin.x / extent.x - 1.0f;
  m[2][1] = 2.0f / extent.z;
  m[3][1] = -2.0f * grid.origin.z / extent.z - 1.0f;
  m[1][2] = -2.0f / extent.y;
  m[3][2] = 2.0f * top / extent.y - 1.0f;
  m[3][3] = 1.0f;
  return m;
}

class SkyColumnsInjection final : public InjectionStrategy {
public:
  explicit SkyColumnsInjection(Params& params)
      : texelsPerCell_(params.get<int>("texels_per_cell", 4, {.min = 1, .max = 16})),
        shiftCells_(params.get<float>("shift", 1.0f, {.min = 0.0f, .max = 4.0f})),
        everyFreeCell_(params.getChoice("fill", "lowest_free_cell", {"lowest_free_cell", "every_free_cell"}) ==
                       "every_free_cell") {}

  void declare(ResourceUses& uses) const override { uses.produces(kSkyLight); }
  std::string cpuRefusal(const Requirements&) const override { return {}; }
  std::string drawsWithGl() const override { return "its top-down depth map (raster/shadow.frag)"; }
  int maxShOrder() const override { return 3; }

  void prepare(const StrategySetup& setup) override {
    ShaderCompiler& shaders = setup.shaders;
    const GridGeometry& grid = setup.grid;
    skyRadiance_ = setup.skyRadiance;
    coefficients_ = shared::shCoefficientCount(setup.requirements.shOrder);
    onCpu_ = runsOnCpu(setup.requirements);
    depthProgram_ = shaders.graphics("raster/scene.vert", "raster/shadow.frag");
    injectProgram_ = shaders.compute(
        "injection/sky_columns.comp",
        {SpecConstant::i(0, shared::shCoefficientCount(setup.requirements.shOrder))});
    width_ = grid.resolution.x * texelsPerCell_;
    height_ = grid.resolution.z * texelsPerCell_;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (std::max(width_, height_) > maxSize)
      throw Error("[injection] sky_columns: texels_per_cell = " + std::to_string(texelsPerCell_) +
                  " makes a " + std::to_string(width_) + "x" + std::to_string(height_) +
                  " depth map, larger than the GL limit " + std::to_string(maxSize) +
                  ": lower texels_per_cell");
    depth_ = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width_, height_, 1, "sky depth");
    framebuffer_.emplace();  // GL objects exist only once prepare() runs in a context
    framebuffer_->attach(GL_DEPTH_ATTACHMENT, depth_);
    glNamedFramebufferDrawBuffer(framebuffer_->id(), GL_NONE);
    glNamedFramebufferReadBuffer(framebuffer_->id(), GL_NONE);
    framebuffer_->checkComplete("sky depth map");
    clipFromWorld_ = skyClipFromWorld(grid);
  }

  std::size_t memoryBytes() const override {
    return depth_.bytes() + hostDepth_.size() * sizeof(float);
  }

  void inject(Frame& frame) override {
    if (!glm::any(glm::greaterThan(skyRadiance_, glm::vec3(0.0f)))) return;
    if (!frame.scene) throw Error("[injection] sky_columns: the frame has no scene to rasterise");
    renderDepth(*frame.scene);
    const GridGeometry& grid = frame.lightGrid.geometry;
    const float texelSize = grid.cellSize / float(texelsPerCell_);
    const glm::vec3 perTexel = skyRadiance_ * (texelSize * texelSize);  // L a, W/sr
    if (onCpu_) return injectOnCpu(frame.lightGrid, perTexel);
    using namespace kernel;
    injectProgram_.use();
    glBindTextureUnit(UNIT_SKY_DEPTH, depth_.id());
    frame.lightGrid.current.bindStorage(BUFFER_GRID);
    glUniform3fv(LOCATION_GRID_ORIGIN, 1, &grid.origin[0]);
    glUniform1f(LOCATION_CELL_SIZE, grid.cellSize);
    glUniform3iv(LOCATION_RESOLUTION, 1, &grid.resolution[0]);
    glUniform1f(LOCATION_SHIFT_CELLS, shiftCells_);
    glUniform3fv(LOCATION_SKY_PER_TEXEL, 1, &perTexel[0]);
    glUniform1i(LOCATION_EVERY_FREE_CELL, everyFreeCell_ ? 1 : 0);
    dispatchCovering({width_, height_, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                     GL_SHADER_STORAGE_BARRIER_BIT);
  }

private:
  // The depth map read back, the grid added to on the host.
  void injectOnCpu(LightGrid& grid, const glm::vec3& perTexel) {
    hostDepth_.resize(std::size_t(width_) * height_);
    glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(hostDepth_.size() * sizeof(float)), hostDepth_.data());
    injectSkyColumnsCpu(hostDepth_, width_, height_, grid.geometry, coefficients_, shiftCells_,
                        perTexel, everyFreeCell_, grid.current.host().data());
  }

  void renderDepth(const SceneGpu& scene) {
    beginRaster(*framebuffer_, width_, height_, 0);
    depthProgram_.use();
    glUniformMatrix4fv(scene_vertex::LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clipFromWorld_[0][0]);
    scene.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  }

  int texelsPerCell_;
  float shiftCells_;
  bool everyFreeCell_;  // the thesis's fill
  glm::vec3 skyRadiance_{0.0f};  // the run's [sky] radiance, W/(m^2 sr)
  int coefficients_ = 4;
  bool onCpu_ = false;
  std::vector<float> hostDepth_;  // on the CPU backend
  int width_ = 0, height_ = 0;
  glm::mat4 clipFromWorld_{1.0f};
  Program depthProgram_, injectProgram_;
  gl::Texture depth_;
  std::optional<gl::Framebuffer> framebuffer_;
};

LPVLAB_REGISTER(InjectionStrategy, "sky_columns",
                "constant sky light down each grid column to its first surface (thesis 5.3)",
                SkyColumnsInjection);

}  // namespace
}  // namespace lpvlab
