// The view grid of a particle model's light field (seed 002: 4.1.2 eq. 4.1, 4.2.1 eq. 4.2-4.4),
// shared by the capture, the billboards that show it and the C++ tests (framework/math/shared.h
// rules: no swizzles, no out-parameters, no arrays; `real` is double in C++).
//
// View (i, j) of a grid of `grid.x` azimuths by `grid.y` elevations looks at the model, in its
// object space, from the unit direction
//     d(i, j) = (cos(theta_j) cos(phi_i), sin(theta_j), cos(theta_j) sin(phi_i)),
//     phi_i = 2 pi i / grid.x,   theta_j = -pi/2 + pi (j + 0.5) / grid.y,
// elevations at the centres of grid.y equal bands, so no view sits on a pole, where the
// azimuth is undefined (seed fig. 4.2: its spherical map distorts there). The seed's eq. 4.1
// turns the model by 2 pi u / density about two axes, which samples the poles densely and
// twice; equal-angle elevation bands sample every latitude once. Views are the layers of a
// texture array, layer = j * grid.x + i.
#ifndef LPVLAB_LIGHT_FIELD_VIEWS_GLSL
#define LPVLAB_LIGHT_FIELD_VIEWS_GLSL

#include "../common/prelude.glsl"

#ifdef LPVLAB_SHARED_CPP
using glm::asin;
using glm::atan;
using glm::cos;
using glm::sin;
#endif

vec3 lightFieldViewDirection(int i, int j, ivec2 grid) {
  real phi = real(2.0) * PI * real(i) / real(grid.x);
  real theta = -real(0.5) * PI + PI * (real(j) + real(0.5)) / real(grid.y);
  return vec3(cos(theta) * cos(phi), sin(theta), cos(theta) * sin(phi));
}

// The continuous grid coordinates (i, j) of a unit direction: view (i, j) at integers, azimuth in
// [0, grid.x), elevation in [-0.5, grid.y - 0.5].
vec2 lightFieldGridCoordinates(vec3 d, ivec2 grid) {
  real phi = atan(d.z, d.x);  // (-pi, pi]
  if (phi < real(0.0)) phi = phi + real(2.0) * PI;
  real theta = asin(clamp(d.y, real(-1.0), real(1.0)));
  real i = phi / (real(2.0) * PI) * real(grid.x);
  if (i >= real(grid.x)) i = i - real(grid.x);
  return vec2(i, (theta + real(0.5) * PI) / PI * real(grid.y) - real(0.5));
}

// The views a billboard shows for a direction and their weights: the nearest view alone
// (`interpolate` false: weight 1 on layer.x), or the four around it with bilinear weights in
// grid coordinates (seed eq. 4.4-4.7), the azimuth wrapping round and the elevation held at the
// first and last band (beyond their centres the nearest band is all there is).
struct LightFieldViews {
  ivec4 layer;
  vec4 weight;
};

int lightFieldLayer(int i, int j, ivec2 grid) {
  int wrapped = i - grid.x * int(floor(real(i) / real(grid.x)));
  int clamped = j < 0 ? 0 : (j > grid.y - 1 ? grid.y - 1 : j);
  return clamped * grid.x + wrapped;
}

LightFieldViews lightFieldViews(vec3 d, ivec2 grid, bool interpolate) {
  vec2 c = lightFieldGridCoordinates(d, grid);
  LightFieldViews v;
  if (!interpolate) {
    int i = int(floor(c.x + real(0.5)));
    int j = int(floor(c.y + real(0.5)));
    int layer = lightFieldLayer(i, j, grid);
    v.layer = ivec4(layer, layer, layer, layer);
    v.weight = vec4(real(1.0), real(0.0), real(0.0), real(0.0));
    return v;
  }
  real cy = clamp(c.y, real(0.0), real(grid.y - 1));
  int i0 = int(floor(c.x));
  int j0 = int(floor(cy));
  real s = c.x - real(i0);
  real t = cy - real(j0);
  v.layer = ivec4(lightFieldLayer(i0, j0, grid), lightFieldLayer(i0 + 1, j0, grid),
                  lightFieldLayer(i0, j0 + 1, grid), lightFieldLayer(i0 + 1, j0 + 1, grid));
  v.weight = vec4((real(1.0) - s) * (real(1.0) - t), s * (real(1.0) - t), (real(1.0) - s) * t, s * t);
  return v;
}

// The image axes of the view from direction d: `right` and `up` with d they make a right-handed
// frame (right x up = d, the viewer looking along -d), `up` the part of the object's +y
// orthogonal to d (+z within 1e-3 of the poles, where +y is nearly along d).
vec3 lightFieldUp(vec3 d) {
  vec3 reference = abs(d.y) > real(0.999) ? vec3(real(0.0), real(0.0), real(1.0))
                                          : vec3(real(0.0), real(1.0), real(0.0));
  return normalize(reference - dot(reference, d) * d);
}

vec3 lightFieldRight(vec3 d) { return cross(lightFieldUp(d), d); }

#endif
