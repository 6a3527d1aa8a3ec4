#pragma once
// A particle model's light field (seed 002, 4.1, with 4.1.1's normals): the model rendered from
// every direction of a grid of azimuths x elevations (shaders/particles/light_field_views.glsl)
// by an orthographic view into one layer of two texture arrays, so that a billboard can show the
// model as seen from near its direction to the viewer, and be lit per pixel:
//   albedo         RGBA16F: the linear albedo times the coverage, and the coverage (alpha);
//   normal_offset  RGBA16F: the object-space normal (turned towards the viewer) and the offset
//                  of the surface from the plane through the model's centre along the view
//                  direction (model units, positive towards the viewer), both times coverage.
// Premultiplied so that the mipmaps (seed 2.4) average covered texels alone: a reader divides by
// the averaged coverage. Layer j * azimuths + i is view (i, j); in a layer, texel (x, y), rows
// from the bottom (GL's order), sees the point radius * ((2 (x + 0.5) / R - 1) right +
// (2 (y + 0.5) / R - 1) up) of the view's plane, `right` and `up` the view's image axes
// (lightFieldRight, lightFieldUp), R the resolution. `radius` is the farthest vertex from the
// model's centre, so the square holds the model from every direction.
//
// The seed renders views into one atlas texture on demand (its cache table); here every view is
// captured when the light field is made: an experiment's particles may be seen from any
// direction, and on llvmpipe capturing 16 x 8 views of the crystal at 64^2 takes milliseconds.
//
// Each view also has the bounds of the model's image in it (its vertices projected onto the
// view's axes, a texel wider each side), in units of the radius ([-1, 1] the whole square): a
// billboard need not cover more than what its views show (billboard.vert), which on the crystal
// is about half of the square.

#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/particles/particle_geometry.h"

namespace lpvlab {

struct LightFieldSettings {
  glm::ivec2 views{16, 8};  // azimuths x elevations, each at least 1
  int resolution = 64;      // texels per side of a view, at least 1
};

class LightField {
public:
  // Captures every view (needs the GL context current). Throws an Error for settings out of range
  // or more views than GL's array textures hold.
  LightField(const ParticleModel& model, const LightFieldSettings& settings, ShaderCompiler& shaders);

  const gl::Texture& albedo() const { return albedo_; }
  const gl::Texture& normalOffset() const { return normalOffset_; }
  const LightFieldSettings& settings() const { return settings_; }
  float radius() const { return radius_; }
  // Per layer: (right min, up min, right max, up max) of the model's image, in units of radius(),
  // within [-1, 1]; as a storage buffer of vec4 for the billboards.
  const std::vector<glm::vec4>& viewBounds() const { return viewBounds_; }
  const gl::Buffer& viewBoundsBuffer() const { return viewBoundsBuffer_; }
  std::size_t memoryBytes() const;  // every level of both arrays

  // Level 0 of one layer of albedo() or normalOffset(), texel (x, y) at [y * resolution + x].
  std::vector<glm::vec4> read(const gl::Texture& texture, int layer) const;

  // View (i, j)'s orthographic clip-from-object matrix (depth from the viewer's side of the
  // square's sphere to the far side).
  static glm::mat4 clipFromObject(int i, int j, glm::ivec2 views, float radius);

private:
  LightFieldSettings settings_;
  float radius_ = 0.0f;
  gl::Texture albedo_, normalOffset_;
  std::vector<glm::vec4> viewBounds_;
  gl::Buffer viewBoundsBuffer_;
};

}  // namespace lpvlab
