#version 450
// A constant colour into two render targets; the colour comes from a specialization constant
// (which the vertex shader lacks) and a uniform (which SPIR-V needs at an explicit location).
layout(constant_id = 3) const float kRed = 0.0;
layout(location = 0) uniform float green;
layout(location = 0) out vec4 first;
layout(location = 1) out vec4 second;

void main() {
  first = vec4(kRed, green, 0.25, 1.0);
  second = vec4(1.0, 2.0, 3.0, 4.0);
}
