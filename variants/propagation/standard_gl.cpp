#include "variants/propagation/standard_gl.h"

#include <string>
#include <utility>
#include <vector>

#include "framework/gl/dispatch.h"
#include "variants/propagation/tiled_walk.h"

namespace lpvlab {
namespace {
namespace kernel {  // gathering's, its tiled layout's and scattering's, the same
#include "shaders/propagation/standard_interface.glsl"
}
}  // namespace

StandardGlKernel::StandardGlKernel(ShaderCompiler& shaders, const StandardGlSettings& settings)
    : settings_(settings) {
  std::vector<SpecConstant> spec{
      SpecConstant::f(0, float(settings.farFace)), SpecConstant::f(1, float(settings.sideFace)),
      SpecConstant::i(2, settings.coefficients), SpecConstant::b(3, settings.withGv),
      SpecConstant::b(4, settings.bounces)};
  if (settings.tiled) {
    tile_ = tiledWalkGroup(settings.coefficients);
    spec.push_back(SpecConstant::i(tiled_walk::SPEC_TILE_X, tile_.x));
    spec.push_back(SpecConstant::i(tiled_walk::SPEC_TILE_Y, tile_.y));
  }
  const std::string path = settings.scatter ? "propagation/standard_scatter.comp"
                           : settings.tiled ? "propagation/standard_gather_tiled.comp"
                                            : "propagation/standard_gather.comp";
  program_ = shaders.compute(path, spec);
}

void StandardGlKernel::propagate(const glm::ivec3& resolution, int iterations,
                                 DualBuffer& current, DualBuffer& scratch,
                                 DualBuffer& accumulated,
                                 const StandardGlOcclusion& occlusion,
                                 int firstIteration) const {
  using namespace kernel;
  program_.use();
  glUniform3iv(LOCATION_RESOLUTION, 1, &resolution[0]);
  // Without a GV the kernels were compiled without its reads, and these uniforms don't exist.
  if (settings_.withGv) {
    glUniform1i(LOCATION_FIRST_OCCLUDED_ITERATION, occlusion.firstOccludedIteration);
    occlusion.blocking->bindStorage(BUFFER_GEOMETRY_VOLUME);
    if (settings_.bounces) occlusion.albedo->bindStorage(BUFFER_GEOMETRY_VOLUME_ALBEDO);
  }
  accumulated.bindStorage(BUFFER_ACCUMULATED);
  for (int i = firstIteration; i < firstIteration + iterations; ++i) {
    if (settings_.withGv) glUniform1i(LOCATION_ITERATION, i);
    current.bindStorage(BUFFER_SOURCE);
    if (settings_.scatter) {
      scratch.zero();  // the atomics add into it
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    scratch.bindStorage(BUFFER_TARGET);
    dispatch(resolution);
    std::swap(current, scratch);  // the new light becomes the next step's source
  }
}

// One step over the grid: a group per 4^3 cell block (simple, scatter), or per tile and z-span
// (tiled).
void StandardGlKernel::dispatch(const glm::ivec3& resolution) const {
  using namespace kernel;
  if (!settings_.tiled)
    return dispatchCovering(resolution, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                            GL_SHADER_STORAGE_BARRIER_BIT);
  dispatchTiledWalk(resolution, tile_);
}

KernelWork standardGlKernelWork(const StandardGlSettings& settings) {
  KernelWork w =
      standardGlTransferWork(settings.coefficients, settings.scatter, settings.withGv);
  if (settings.bounces) w.multiplyAdds *= 2;
  if (settings.tiled) w.bytes -= tiledWalkBytesSaved(settings.coefficients);
  return w;
}

}  // namespace lpvlab
