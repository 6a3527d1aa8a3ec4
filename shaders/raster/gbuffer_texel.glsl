// What the camera's G-buffer stores of a surface point: its position (w = 1: covered) and its
// unit normal turned to face the camera (surfaces are two-sided), w the view depth along the
// camera's forward axis (m). gbuffer_output.glsl writes it on GL; the ray-cast raster passes
// (framework/raster) on the CPU. Written in the shared subset (prelude.glsl): C++ compiles it too.
#ifndef LPVLAB_GBUFFER_TEXEL_GLSL
#define LPVLAB_GBUFFER_TEXEL_GLSL

struct GBufferTexel {
  vec4 position;
  vec4 normal;
};

GBufferTexel gbufferTexel(vec3 worldPosition, vec3 worldNormal, vec3 cameraPosition,
                          vec3 cameraForward) {
  vec3 n = normalize(worldNormal);
  if (dot(n, cameraPosition - worldPosition) < 0.0) n = -n;
  GBufferTexel texel;
  texel.position = vec4(worldPosition, 1.0);
  texel.normal = vec4(n, dot(worldPosition - cameraPosition, cameraForward));
  return texel;
}

#endif
