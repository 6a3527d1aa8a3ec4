#pragma once
// What [compute] raster = "auto" weighs per raster pass on a software GL renderer: the pass's
// time on llvmpipe's rasteriser against its time by ray casting (ray_raster.h), from a model of
// each fitted to frames measured on a 2-core x86-64 VM (Intel Xeon, AVX-512; Mesa 22.3 llvmpipe,
// Embree 3.13; docs/benchmarks.md#raster-passes):
//   llvmpipe:     triangles drawn x views x 200 ns  +  texels x (1 ns depth only, 20 ns colour)
//   ray casting:  texels x (15 ns depth only, 60 ns colour: shading and texture lookups)
// llvmpipe's cost grows with the triangles it sets up, once per view; a ray's only with the log
// of the triangles (the BVH). On the Cornell box (30 triangles) every pass is faster on
// llvmpipe; in Sponza (262k triangles) the G-buffer and the RSM are 5x and 3x faster by rays,
// a 2048^2 shadow map 1.1x slower. The model only picks where a pass runs: the times a run
// reports are measured.

namespace lpvlab {

struct RasterPassWork {
  double texels = 0.0;     // over every view
  double views = 1.0;      // times the triangles are drawn
  double triangles = 0.0;  // drawn per view
  bool colour = true;      // writes colour targets (G-buffer, RSM), not only depth (shadow maps)
};

struct RasterPassCost {
  double llvmpipeMs = 0.0;
  double raysMs = 0.0;
  bool raysFaster() const { return raysMs < llvmpipeMs; }
};

RasterPassCost estimateRasterPass(const RasterPassWork& work);

}  // namespace lpvlab
