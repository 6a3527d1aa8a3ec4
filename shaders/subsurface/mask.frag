#version 450
// The camera pixels that see a translucent surface (1) or any other (0): the subsurface LPV adds
// light to the former only. Drawn with the G-buffer's camera, vertex shader and depth test, so
// each pixel sees the G-buffer's surface.
#include "translucency.glsl"

layout(location = 2) in vec2 texcoord;

layout(location = 0) out vec4 outMask;

void main() {
  materialAlbedo(texcoord);
  outMask = vec4(materialTranslucent() ? 1.0 : 0.0);
}
