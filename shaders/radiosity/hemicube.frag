#version 450
// Writes which side of which patch covers the pixel: 2 patch + 1 for its front (the side its
// winding faces), 2 patch + 2 for its back; 0, the clear value, where nothing is seen.
layout(location = 0) flat in uint patchIndex;
layout(location = 0) out uint side;

void main() {
  side = 2u * patchIndex + (gl_FrontFacing ? 1u : 2u);
}
