#version 450
// Depth-only pass of surfaces without an alpha mask (shadow maps): no fragment work at all, so
// the rasteriser keeps its early depth test. On llvmpipe this makes the Cornell box's five
// 1024^2 shadow views 4.8x cheaper than running the material's alpha test (shadow.frag) for
// surfaces that cannot cut anything out.
void main() {}
