// The interface of the tiled gathers' walk (tiled_walk.glsl: standard_gather_tiled.comp,
// directed_gather_tiled.comp), shared with their C++ side (variants/propagation/tiled_walk.h):
// a work group is a tile of one z-plane, its size the specialisation constants SPEC_TILE_X and
// SPEC_TILE_Y, and it walks TILED_Z_SPAN planes up the grid. Plain `const int`s, valid GLSL and C++.
const int SPEC_TILE_X = 5;
const int SPEC_TILE_Y = 6;
const int TILED_GROUP_SIZE_Z = 1;  // a tile is one plane thick
const int TILED_Z_SPAN = 8;
