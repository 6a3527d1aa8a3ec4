#version 450
// Every invocation adds 1.0 to one float in a buffer and to one texel of an r32f image.
#extension GL_EXT_shader_atomic_float : require
layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Sum { float sum; };
layout(binding = 0, r32f) uniform image2D image;

void main() {
  atomicAdd(sum, 1.0);
  imageAtomicAdd(image, ivec2(0, 0), 1.0);
}
