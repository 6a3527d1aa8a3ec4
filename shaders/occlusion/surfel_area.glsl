// The area of the surface patch one texel of a view sees (a surfel of the geometry volume),
// shared by the GV injection kernels and C++ tests.
//
// Perspective view (the camera, a cube face of a point or spot light): a texel is a square of
// edge t on the image plane at unit depth (t = 2 tan(fov / 2) / resolution). Seen from the eye,
// a texel at angle theta from the view axis subtends Omega = t^2 cos^3(theta) sr; at the surface,
// distance r = depth / cos(theta) away, it covers Omega r^2 = t^2 depth^3 / r perpendicular to
// the ray, and on a surface whose normal makes angle alpha with the direction to the eye
//     A = t^2 depth^3 / (r |cos alpha|).
// Orthographic view (a directional light's box of width W): A = (W / resolution)^2 / |cos alpha|.
// 1/|cos alpha| is clamped at 1 / GV_MIN_COSINE: a texel that grazes a surface stands for a long
// thin strip whose area is real, but all of it lands in the one GV cell of the texel's centre, so
// without the clamp single grazing texels would make whole cells opaque.
#ifndef LPVLAB_SURFEL_AREA_GLSL
#define LPVLAB_SURFEL_AREA_GLSL
#include "../common/prelude.glsl"

const real GV_MIN_COSINE = 0.1;  // surfaces seen at more than ~84 degrees count as seen at 84

real surfelInverseCosine(real cosine) {
  return 1.0 / max(abs(cosine), GV_MIN_COSINE);
}

real perspectiveSurfelArea(real texelEdge, real depth, real distance, real cosine) {
  return texelEdge * texelEdge * depth * depth * depth / distance * surfelInverseCosine(cosine);
}

real orthographicSurfelArea(real texelEdge, real cosine) {
  return texelEdge * texelEdge * surfelInverseCosine(cosine);
}

#endif
