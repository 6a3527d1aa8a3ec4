// [indirect] method = "instant_radiosity": Keller's instant radiosity (seed 001, 2.1-2.6). Each
// frame, `light_paths` random walks from the lights leave VPLs where they hit surfaces
// (framework/many_lights/light_paths.h); every pixel of the G-buffer is then lit by every VPL
// (framework/many_lights/vpl_gather.h). Parameters (docs/methods.md):
//   light_paths     walks per frame (VPLs: about light_paths / (1 - mean albedo), fewer with
//                   one_bounce)
//   one_bounce      VPLs only where light first lands: one-bounce indirect light, what the
//                   reference's `indirect1` holds (default false: every bounce, `indirect`)
//   roulette_after  VPLs a walk makes before Russian roulette may end it
//   max_bounces     the most VPLs one walk makes
//   visibility      "rays": exact, an Embree shadow ray per (pixel, VPL) pair; "shadow_maps": a
//                   paraboloid shadow map per VPL (2.4), its texels' depths by Embree rays, with
//                   shadow_map_size, normal_offset (texels) and depth_bias (relative); "none": V = 1
//   clamp           c of min(c, G f_r) in 1/(m^2 sr) (equation 12); 0: no clamp. The manifest
//                   reports what it removed (indirect_method.statistics.clamp)
//   clamp_compensation   true: the light the clamp removed, estimated by a short path-traced
//                   gather where the clamp acts and added back (Kollig and Keller 2004;
//                   framework/many_lights/clamp_compensation.h), with compensation_samples
//                   directions per pixel; statistics.clamp.compensation reports it
//   specular_albedo, exponent   a glossy lobe on every receiver (the reference's modified Phong)
//   sphere_radius   virtual spherical lights of this radius (m; 0: points): each VPL's light
//                   integrated over the cone its sphere subtends (framework/many_lights/
//                   vpl_transfer.h)
//   seed            of the walks; the same VPLs every frame while nothing moves
// Runs on the CPU (Embree): framework/many_lights/vpl_method.h.

#include "framework/many_lights/vpl_method.h"

namespace lpvlab {

namespace {

class InstantRadiosity : public LightPathMethod {
public:
  explicit InstantRadiosity(Params& p) : LightPathMethod(p, readExactOrMappedVisibility(p)) {}
};

}  // namespace

LPVLAB_REGISTER(IndirectMethod, "instant_radiosity",
                "VPLs from random walks of light paths, gathered per pixel with exact (Embree), "
                "shadow-mapped or no visibility and the clamp min(c, G f_r) (Keller 1997; seed "
                "001, 2)",
                InstantRadiosity);

}  // namespace lpvlab
