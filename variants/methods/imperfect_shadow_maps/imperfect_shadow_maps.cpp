// [indirect] method = "imperfect_shadow_maps": instant radiosity whose VPLs see the scene through
// imperfect shadow maps (Ritschel et al. 2008; seed 001, 3.3). Each VPL's paraboloid map, one of
// many in an atlas, is made by splatting its own set of points sampled uniformly over the scene's
// surfaces (the nearest depth per texel); the texels no point reached are filled by the two-pass
// pull-push of 3.3.1 (framework/many_lights/pull_push.h). Far cheaper than a shadow map per VPL
// rendered from the triangles, and wrong where the points are too sparse. Parameters
// (docs/methods.md):
//   points_per_vpl   points splatted into each VPL's map
//   shadow_map_size  texels per side of a VPL's map (a power of two)
//   pull_push_levels coarser levels pull-push may make (0: no hole filling)
//   normal_offset, depth_bias   the shadow-map test (framework/many_lights/vpl_depth_maps.h)
//   and the VPL keys of instant radiosity: light_paths, one_bounce, roulette_after, max_bounces,
//   clamp, clamp_compensation, compensation_samples, specular_albedo, exponent, sphere_radius, seed.
// The manifest reports the share of texels that were holes before and after pull-push.

#include "framework/many_lights/vpl_method.h"

namespace lpvlab {

namespace {

ImperfectSettings readImperfect(Params& p) {
  ImperfectSettings s;
  s.pointsPerVpl = p.get<int>("points_per_vpl", 1024, {.min = 1, .max = 1 << 22});
  s.pullPushLevels = p.get<int>("pull_push_levels", 4, {.min = 0, .max = 16});
  return s;
}

class ImperfectShadowMaps : public LightPathMethod {
public:
  explicit ImperfectShadowMaps(Params& p)
      : LightPathMethod(p, VplVisibility::Imperfect, readImperfect(p)) {}
};

}  // namespace

LPVLAB_REGISTER(IndirectMethod, "imperfect_shadow_maps",
                "instant radiosity with imperfect shadow maps: points splatted into a paraboloid "
                "map per VPL, holes filled by pull-push (Ritschel et al. 2008; seed 001, 3.3)",
                ImperfectShadowMaps);

}  // namespace lpvlab
