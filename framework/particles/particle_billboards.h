#pragma once
// Light-field particles in the LPV pipeline (seed 002, 4.2): each particle a billboard facing
// the pass's viewer that shows its model's light field (light_field.h) as seen along its
// direction to that viewer, drawn by the camera's G-buffer and by every light view's shadow map
// and RSM (extra_geometry.h) after the scene's meshes. So the particles are lit per pixel from the
// light field's normals by the direct light with shadows and by the grid, cast the shadow of the
// model's silhouette as the light sees it and reflect light into the grid, like the geometry
// they stand for (shaders/particles/light_field_sample.glsl says how a fragment is made).
//
// ParticleBillboardSet gives every light-field system of an experiment its billboards and keeps
// their particles at the frame's time.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/particles/light_field.h"
#include "framework/particles/particle_geometry.h"
#include "framework/pipeline/extra_geometry.h"

namespace lpvlab {

class Pipeline;

struct ParticleInstanceGpu {  // std430 mirror of shaders/particles/particle_instance.glsl
  glm::vec4 positionSize;     // world position (m), size (m)
  glm::vec4 orientation;      // unit quaternion x, y, z, w: object to world
  glm::vec4 tint;             // colour multiplying the albedo
};
static_assert(sizeof(ParticleInstanceGpu) == 48);

class ParticleBillboards : public ExtraGeometry {
public:
  // Captures the light field and compiles the three passes' programs (GL context current).
  ParticleBillboards(const ParticleModel& model, const ParticleDrawing& drawing, std::size_t capacity,
                     ShaderCompiler& shaders);
  ~ParticleBillboards() override;
  ParticleBillboards(const ParticleBillboards&) = delete;
  ParticleBillboards& operator=(const ParticleBillboards&) = delete;

  // The particles to draw from now on (at most the capacity given).
  void update(const std::vector<Particle>& particles);
  void draw(const RasterView& view) const override;

  const LightField& lightField() const { return field_; }
  std::size_t count() const { return count_; }
  std::size_t memoryBytes() const { return field_.memoryBytes() + instances_.size(); }

private:
  ParticleDrawing drawing_;
  LightField field_;
  Program gbuffer_, shadow_, rsm_;
  gl::Buffer instances_;
  std::size_t capacity_ = 0, count_ = 0;
  GLuint vertexArray_ = 0;  // none of the billboards' vertices comes from a buffer
};

class ParticleBillboardSet {
public:
  // Billboards for every system of `particles` drawn as a light field, with the particles alive at
  // `seconds`, drawn by `pipeline`'s raster passes from its next frame on.
  ParticleBillboardSet(const std::vector<ParticleGeometry>& particles, double seconds,
                       ShaderCompiler& shaders, Pipeline& pipeline);
  // The particles alive at `seconds`.
  void place(double seconds);
  bool empty() const { return billboards_.empty(); }

private:
  const std::vector<ParticleGeometry>& particles_;
  std::vector<std::pair<std::size_t, std::unique_ptr<ParticleBillboards>>> billboards_;  // by system
};

}  // namespace lpvlab
