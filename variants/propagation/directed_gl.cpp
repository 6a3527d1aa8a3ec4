#include "variants/propagation/directed_gl.h"

#include <utility>
#include <vector>

#include "framework/gl/dispatch.h"
#include "framework/math/solid_angle.h"
#include "framework/math/shared.h"
#include "variants/propagation/tiled_walk.h"

namespace lpvlab {
namespace {
namespace dilate_kernel {
#include "shaders/propagation/directed_dilate_interface.glsl"
}
namespace gather_kernel {
#include "shaders/propagation/directed_gather_interface.glsl"
}
namespace release_kernel {
#include "shaders/propagation/directed_release_interface.glsl"
}

}  // namespace

KernelWork directedGlWork(const DirectedGlSettings& settings) {
  const double n = settings.coefficients;
  KernelWork w = standardGlTransferWork(settings.coefficients, false, settings.withGv);
  w.multiplyAdds += 3 * 30 * 8 + 60 * 8 + 3 * n;
  w.bytes += 16 * ((settings.dilation ? 7 : 0) + 1);
  if (settings.tiled) w.bytes -= tiledWalkBytesSaved(settings.coefficients);
  // Scattering finds each receiver's gain once per sender (six times a cell, not once) and adds
  // its light with read-modify-writes of the receiver's coefficients (and the accumulated grid's).
  if (settings.scatter) {
    w.multiplyAdds += 5 * 60 * 8;
    w.bytes += 6 * 16 + 6 * 2 * 2 * 4 * 3 * n;
  }
  if (settings.release) {
    const KernelWork free = standardGlKernelWork({.coefficients = settings.coefficients,
                                                  .withGv = settings.withGv,
                                                  .scatter = settings.scatter,
                                                  .tiled = settings.tiled});
    w.multiplyAdds += free.multiplyAdds;
    w.bytes += free.bytes + 4 * 4 * 3 * n + 16 * 7;
  }
  return w;
}

DirectedGlKernel::DirectedGlKernel(ShaderCompiler& shaders, const DirectedGlSettings& settings,
                                   const glm::ivec3& resolution)
    : settings_(settings) {
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  const int coefficients = settings.coefficients;
  std::vector<SpecConstant> spec{SpecConstant::f(0, float(angles.farFace)),
                                 SpecConstant::f(1, float(angles.sideFace)),
                                 SpecConstant::b(2, settings.withGv), SpecConstant::i(3, coefficients)};
  if (settings.tiled) {
    tile_ = tiledWalkGroup(coefficients);
    spec.push_back(SpecConstant::i(tiled_walk::SPEC_TILE_X, tile_.x));
    spec.push_back(SpecConstant::i(tiled_walk::SPEC_TILE_Y, tile_.y));
  }
  gather_ = shaders.compute(settings.scatter  ? "propagation/directed_scatter.comp"
                            : settings.tiled ? "propagation/directed_gather_tiled.comp"
                                             : "propagation/directed_gather.comp",
                            spec);
  dilate_ = shaders.compute("propagation/directed_dilate.comp");
  const std::size_t cells = std::size_t(shared::cellCount(resolution));
  const std::size_t gridBytes = 3 * std::size_t(coefficients) * cells * sizeof(float);
  scratch_ = DualBuffer(gridBytes, "light grid (propagation scratch)");
  if (settings.release) {
    release_ = shaders.compute(
        "propagation/directed_release.comp",
        {SpecConstant::i(0, coefficients), SpecConstant::f(1, float(settings.cosRegionAngle))});
    free_ = StandardGlKernel(shaders, {.coefficients = coefficients,
                                       .farFace = angles.farFace,
                                       .sideFace = angles.sideFace,
                                       .withGv = settings.withGv,
                                       .scatter = settings.scatter,
                                       .tiled = settings.tiled});
    for (DualBuffer& b : freeLight_)
      b = DualBuffer(gridBytes, "light grid (directed propagation's free light)");
  }
  if (settings.dilation) {
    const std::size_t normalBytes = 4 * cells * sizeof(float);
    for (gl::Buffer& b : normals_) b = gl::Buffer(normalBytes, "dilated normals");
  }
}

void DirectedGlKernel::propagate(const glm::ivec3& res, int iterations, DualBuffer& current,
                                 DualBuffer& accumulated, const gl::Buffer& injectedNormals,
                                 const gl::Buffer* gv, int firstOccludedIteration) {
  const gl::Buffer* normals = &injectedNormals;
  if (settings_.release) {
    freeLight_[0].zero();  // the grid's current light starts attached
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  const StandardGlOcclusion occlusion{.blocking = gv,
                                      .firstOccludedIteration = firstOccludedIteration};
  for (int i = 0; i < iterations; ++i) {
    if (settings_.dilation) {
      using namespace dilate_kernel;
      gl::Buffer& next = normals_[i % 2];
      dilate_.use();
      glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
      normals->bindStorage(BUFFER_SOURCE);
      next.bindStorage(BUFFER_TARGET);
      dispatchCovering(res, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                       GL_SHADER_STORAGE_BARRIER_BIT);
      normals = &next;
    }
    if (settings_.release) {
      releaseLight(res, current, *normals, false);
      // One standard gathering step of the free light, added to the accumulated grid.
      free_.propagate(res, 1, freeLight_[0], freeLight_[1], accumulated, occlusion, i);
    }
    using namespace gather_kernel;
    gather_.use();
    glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
    // Only a kernel specialised with the GV keeps this uniform (GL refuses setting a removed one).
    if (settings_.withGv) glUniform1i(LOCATION_OCCLUDE_THIS_ITERATION, i >= firstOccludedIteration);
    current.bindStorage(BUFFER_SOURCE);
    scratch_.bindStorage(BUFFER_TARGET);
    accumulated.bindStorage(BUFFER_ACCUMULATED);
    normals->bindStorage(BUFFER_NORMALS);
    if (settings_.withGv) gv->bindStorage(BUFFER_GEOMETRY_VOLUME);
    if (settings_.scatter) {  // the senders add into the next light: it starts empty
      scratch_.zero();
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    if (settings_.tiled)
      dispatchTiledWalk(res, tile_);
    else
      dispatchCovering(res, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                       GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(current, scratch_);  // the new light becomes the next step's source
  }
  if (settings_.release && iterations > 0) {
    // The grid's current light: the last step's attached and free light together.
    releaseLight(res, current, *normals, true);
    std::swap(current, freeLight_[0]);
  }
}

void DirectedGlKernel::releaseLight(const glm::ivec3& res, DualBuffer& current,
                                    const gl::Buffer& normals, bool all) {
  using namespace release_kernel;
  release_.use();
  glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
  glUniform1i(LOCATION_RELEASE_ALL, all ? 1 : 0);
  normals.bindStorage(BUFFER_NORMALS);
  current.bindStorage(BUFFER_ATTACHED);
  freeLight_[0].bindStorage(BUFFER_FREE);
  dispatchCovering(res, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_SHADER_STORAGE_BARRIER_BIT);
}

std::size_t DirectedGlKernel::memoryBytes() const {
  return scratch_.size() + freeLight_[0].size() + freeLight_[1].size() + normals_[0].size() +
         normals_[1].size();
}

}  // namespace lpvlab
