#include "framework/raster/raster_cost.h"

namespace lpvlab {

namespace {

// The model's constants (raster_cost.h), nanoseconds.
constexpr double kLlvmpipePerTriangle = 200.0;
constexpr double kLlvmpipePerDepthTexel = 1.0, kLlvmpipePerColourTexel = 20.0;
constexpr double kRaysPerDepthTexel = 15.0, kRaysPerColourTexel = 60.0;

}  // namespace

RasterPassCost estimateRasterPass(const RasterPassWork& work) {
  const double llvmpipeNs = work.triangles * work.views * kLlvmpipePerTriangle +
                            work.texels * (work.colour ? kLlvmpipePerColourTexel : kLlvmpipePerDepthTexel);
  const double raysNs = work.texels * (work.colour ? kRaysPerColourTexel : kRaysPerDepthTexel);
  return {llvmpipeNs * 1e-6, raysNs * 1e-6};
}

}  // namespace lpvlab
