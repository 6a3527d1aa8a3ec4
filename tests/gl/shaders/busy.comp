#version 450
// Work that takes measurable time: every invocation iterates a chaotic map, and the result is
// stored so that the compiler cannot drop the loop.
layout(local_size_x = 64) in;
layout(constant_id = 0) const int kIterations = 1000;
layout(std430, binding = 0) buffer Out { float values[]; };

void main() {
  float x = float(gl_GlobalInvocationID.x) * 1e-6 + 0.1;
  for (int i = 0; i < kIterations; ++i) x = 3.9 * x * (1.0 - x);
  values[gl_GlobalInvocationID.x] = x;
}
