#pragma once
// Turning the scene's lights into the views that shadow maps and RSMs are rendered from:
//   point and spot lights: the six 90-degree faces of a cube around the light, skipping the faces
//     whose frustum cannot meet the spot's cone (a spot pointing down renders no upward face);
//   directional lights: one orthographic view covering the scene bounds, or, following the
//     camera, a box around a point ahead of it (DirectionalFollow; thesis 6.2).
// A cube face's texel subtends (2 tan(fov/2) / N)^2 / (1 + x^2 + y^2)^(3/2) sr at the light, so an
// RSM texel's reflected flux is albedo * I(w) * that solid angle, whatever the surface's slope.

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "framework/math/bounds.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// std430 mirrors of shaders/common/lights_gpu.glsl.
struct GpuLight {
  glm::vec4 positionType;
  glm::vec4 directionCosOuter;
  glm::vec4 intensityCosInner;
  glm::ivec4 viewOfFace0123;
  glm::ivec4 viewOfFace45;
};
static_assert(sizeof(GpuLight) == 80);

struct GpuView {
  glm::mat4 clipFromWorld;
  glm::vec4 params;
};
static_assert(sizeof(GpuView) == 80);

// A record as the shared GLSL's GpuLight and GpuView compile as C++ (framework/math/shared.h,
// in the translation unit's precision; each translation unit has its own such types, so the
// caller names them): for CPU kernels that call the GL kernels' shared functions.
template <class SharedLight>
SharedLight sharedLightRecord(const GpuLight& light) {
  using Vec4 = decltype(SharedLight::positionType);
  return {Vec4(light.positionType), Vec4(light.directionCosOuter), Vec4(light.intensityCosInner),
          light.viewOfFace0123, light.viewOfFace45};
}
template <class SharedView>
SharedView sharedViewRecord(const GpuView& view) {
  using Vec4 = decltype(SharedView::params);
  using Mat4 = decltype(SharedView::clipFromWorld);
  return {Mat4(view.clipFromWorld), Vec4(view.params)};
}

struct LightViews {
  std::vector<GpuLight> lights;
  std::vector<GpuView> views;
};

template <class SharedLight, class SharedView>
struct SharedLightViews {
  std::vector<SharedLight> lights;
  std::vector<SharedView> views;
};

// Every record of `records` as the shared types (see sharedLightRecord).
template <class SharedLight, class SharedView>
SharedLightViews<SharedLight, SharedView> sharedLightViews(const LightViews& records) {
  SharedLightViews<SharedLight, SharedView> shared;
  for (const GpuLight& light : records.lights)
    shared.lights.push_back(sharedLightRecord<SharedLight>(light));
  for (const GpuView& view : records.views) shared.views.push_back(sharedViewRecord<SharedView>(view));
  return shared;
}

// A directional light's view that follows the camera, as the thesis's shadow camera follows its
// main camera (seed 000, 6.2): `halfWidth` metres each side of `centre` across the light, and
// along the light over the whole scene (so every occluder of the box casts into it). The texels
// then cover only that region, more finely than a box around the whole scene, and nothing outside
// it is lit directly or injected.
// With `texel` > 0 the centre is moved to the nearest multiple of `texel` along the view's two
// image axes first (the thesis's "rotate back to the axes, round to whole texels, rotate
// forward"): the texel grid then stays fixed in the world while the camera moves, so the maps only
// ever shift by whole texels. `texel` = 0 follows every move (an ablation: sub-texel moves resample
// the maps, and shadows and VPLs shimmer).
struct DirectionalFollow {
  glm::vec3 centre{0.0f};
  float halfWidth = 1.0f;  // metres
  float texel = 0.0f;      // snapping step, metres (0: none)
};

// The snapping step that keeps both maps' texel grids fixed: a whole number of texels of the RSM
// (rsmResolution per side) and of the shadow map (shadowResolution) over the box's width.
float directionalSnapStep(float halfWidth, int rsmResolution, int shadowResolution);

// Throws an Error when a light can't be used (zero or negative intensity is allowed: it gives
// black; non-finite values and degenerate directions are errors). Without `follow`, a directional
// light's view is an orthographic box around the scene's bounding sphere, which no camera move
// changes.
LightViews buildLightViews(const std::vector<Light>& lights, const Bounds& sceneBounds,
                           const std::optional<DirectionalFollow>& follow = std::nullopt);

// Where view `view` looks from: its light's position (w = 1) or, for a directional light, the
// unit direction towards the light (w = 0).
glm::vec4 lightViewViewer(const LightViews& views, int view);

}  // namespace lpvlab
