#version 450
// A fragment shader that takes measurable time (see busy.comp).
layout(constant_id = 0) const int kIterations = 1000;
layout(location = 0) out vec4 colour;

void main() {
  float x = gl_FragCoord.x * 1e-4 + 0.1;
  for (int i = 0; i < kIterations; ++i) x = 3.9 * x * (1.0 - x);
  colour = vec4(x);
}
