#version 450
// Writes its specialization constants where the test can read them back.
layout(local_size_x_id = 0) in;
layout(constant_id = 1) const int kInt = 1;
layout(constant_id = 2) const float kFloat = 1.0;
layout(std430, binding = 0) buffer Out {
  uint localSize;
  int intValue;
  float floatValue;
  uint invocations;
};

void main() {
  if (gl_GlobalInvocationID.x == 0) {
    localSize = gl_WorkGroupSize.x;
    intValue = kInt;
    floatValue = kFloat;
  }
  atomicAdd(invocations, 1u);
}
