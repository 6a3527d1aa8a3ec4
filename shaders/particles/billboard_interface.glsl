// The interface of billboard.vert and light_field_sample.glsl, shared with their C++ side
// (framework/particles/particle_billboards.cpp): binding points and uniform locations, defined
// here once (beside the pass's own: gbuffer_output.glsl's and rsm_output.glsl's use locations 2
// and 3, buffers 1 and 2). Plain `const int`s, valid GLSL and C++.
const int LOCATION_BILLBOARD_CLIP_FROM_WORLD = 0;  // uniform mat4 clipFromWorld
const int LOCATION_VIEWER = 4;        // uniform vec4 viewer: position (w = 1) or unit direction towards it (w = 0)
const int LOCATION_VIEW_GRID = 5;     // uniform ivec2 viewGrid: azimuths, elevations
const int LOCATION_RADIUS = 6;        // uniform float radius: a view's half-width, model units
const int LOCATION_INTERPOLATE = 7;   // uniform int interpolate: 1 blends four views, 0 the nearest
const int BUFFER_INSTANCES = 3;       // storage buffer: ParticleInstance[]
const int BUFFER_VIEW_BOUNDS = 4;     // storage buffer: vec4 per light-field view, its image's bounds
const int UNIT_LIGHT_FIELD_ALBEDO = 1;  // texture unit: sampler2DArray albedo (premultiplied)
const int UNIT_LIGHT_FIELD_NORMAL = 2;  // texture unit: sampler2DArray normal and offset (premultiplied)
