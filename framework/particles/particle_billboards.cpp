#include "framework/particles/particle_billboards.h"

#include "framework/core/error.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

namespace billboard_kernel {
#include "shaders/particles/billboard_interface.glsl"
}
namespace gbuffer_kernel {
#include "shaders/raster/gbuffer_interface.glsl"
}
namespace rsm_kernel {
#include "shaders/raster/rsm_interface.glsl"
}

ParticleBillboards::ParticleBillboards(const ParticleModel& model, const ParticleDrawing& drawing,
                                       std::size_t capacity, ShaderCompiler& shaders)
    : drawing_(drawing),
      field_(model, LightFieldSettings{.views = drawing.views, .resolution = drawing.resolution}, shaders),
      gbuffer_(shaders.graphics("particles/billboard.vert", "particles/billboard_gbuffer.frag")),
      shadow_(shaders.graphics("particles/billboard.vert", "particles/billboard_shadow.frag")),
      rsm_(shaders.graphics("particles/billboard.vert", "particles/billboard_rsm.frag")),
      instances_(std::max<std::size_t>(capacity, 1) * sizeof(ParticleInstanceGpu), "particle instances"),
      capacity_(capacity) {
  glCreateVertexArrays(1, &vertexArray_);
}

ParticleBillboards::~ParticleBillboards() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void ParticleBillboards::update(const std::vector<Particle>& particles) {
  if (particles.size() > capacity_)
    throw Error("particle billboards: " + std::to_string(particles.size()) + " particles exceed the " +
                std::to_string(capacity_) + " they were made for");
  std::vector<ParticleInstanceGpu> instances;
  instances.reserve(particles.size());
  for (const Particle& p : particles) {
    const glm::quat q(p.orientation);
    instances.push_back({glm::vec4(glm::vec3(p.position), float(p.size)), glm::vec4(q.x, q.y, q.z, q.w),
                         glm::vec4(glm::vec3(p.color), 1.0f)});
  }
  if (!instances.empty()) instances_.upload(instances.data(), instances.size() * sizeof(ParticleInstanceGpu));
  count_ = instances.size();
}

void ParticleBillboards::draw(const RasterView& view) const {
  if (count_ == 0 || (view.target == RasterTarget::Rsm && !drawing_.inject)) return;
  using namespace billboard_kernel;
  const Program& program = view.target == RasterTarget::GBuffer ? gbuffer_
                           : view.target == RasterTarget::ShadowMap ? shadow_ : rsm_;
  program.use();
  glUniformMatrix4fv(LOCATION_BILLBOARD_CLIP_FROM_WORLD, 1, GL_FALSE, &view.clipFromWorld[0][0]);
  glUniform4fv(LOCATION_VIEWER, 1, &view.viewer[0]);
  glUniform2i(LOCATION_VIEW_GRID, drawing_.views.x, drawing_.views.y);
  glUniform1f(LOCATION_RADIUS, field_.radius());
  const bool interpolate =
      drawing_.interpolate && (view.target != RasterTarget::ShadowMap || drawing_.interpolateShadows);
  glUniform1i(LOCATION_INTERPOLATE, interpolate ? 1 : 0);
  if (view.target == RasterTarget::GBuffer) {
    glUniform3fv(gbuffer_kernel::LOCATION_CAMERA_POSITION, 1, &view.cameraPosition[0]);
    glUniform3fv(gbuffer_kernel::LOCATION_CAMERA_FORWARD, 1, &view.cameraForward[0]);
  } else if (view.target == RasterTarget::Rsm) {
    glUniform1i(rsm_kernel::LOCATION_VIEW_INDEX, view.viewIndex);
    glUniform1i(rsm_kernel::LOCATION_RESOLUTION, view.resolution);
  }
  instances_.bindStorage(BUFFER_INSTANCES);
  field_.viewBoundsBuffer().bindStorage(BUFFER_VIEW_BOUNDS);
  glBindTextureUnit(UNIT_LIGHT_FIELD_ALBEDO, field_.albedo().id());
  glBindTextureUnit(UNIT_LIGHT_FIELD_NORMAL, field_.normalOffset().id());
  glBindVertexArray(vertexArray_);
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(count_));
  glBindVertexArray(0);
}

ParticleBillboardSet::ParticleBillboardSet(const std::vector<ParticleGeometry>& particles, double seconds,
                                           ShaderCompiler& shaders, Pipeline& pipeline)
    : particles_(particles) {
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleGeometry& system = particles[s];
    if (!system.drawing().lightField) continue;
    billboards_.emplace_back(s, std::make_unique<ParticleBillboards>(system.model(), system.drawing(),
                                                                     system.system().capacity(), shaders));
    pipeline.addExtraGeometry(billboards_.back().second.get());
  }
  place(seconds);
}

void ParticleBillboardSet::place(double seconds) {
  for (auto& [system, billboards] : billboards_)
    billboards->update(particlesAt(particles_[system].system(), seconds));
}

}  // namespace lpvlab
