#pragma once
// A particle system's copies of its model as triangles of the scene: one mesh per mesh of the
// model, with room for the most particles ever alive (ParticleSystem::capacity), filled anew
// for every frame. Every renderer then draws the particles as the geometry they are: the LPV
// pipeline (G-buffer, shadow maps, RSMs, so they are lit, cast shadows and inject), the path
// tracer (the reference) and the other methods, with the same transforms by construction.
//
// Particle k of an emitter keeps slot k mod capacity(emitter) for its whole life (the births
// alive at once are consecutive and fewer than the capacity, so slots never collide); an empty
// slot's triangles collapse onto the emitter's centre, where they cover no pixel and no ray
// hits them.
//
// The model is centred on the centre of its bounds and scaled so that its largest extent is 1;
// a particle of size s is that shape scaled by s, turned by its orientation, at its position.
// Its colour multiplies the model's albedo: one colour for the system goes into the copies'
// materials; colour keys over the life go into the copies' vertex colours (Mesh::colors), each
// slot's set as it is placed, which every renderer reads like the material's.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "framework/particles/particle_system.h"
#include "framework/scene/scene.h"

namespace lpvlab {

struct ParticleModel {
  std::string source;             // the file it came from (for messages)
  std::vector<Mesh> meshes;       // object space: centred, largest extent 1
  std::vector<Material> materials;  // their base colour textures index `textures`
  std::vector<TextureImage> textures;
  std::size_t triangleCount() const;
};

// The meshes of `file` named in `meshNames` (all of them when empty), with their materials,
// centred and scaled. Throws an Error naming a mesh the file lacks, or when the meshes have no
// extent or emit light (an emitting particle would be a light lpvlab's light sampling does not
// know).
ParticleModel particleModel(const Scene& file, const std::vector<std::string>& meshNames);

// How the LPV pipeline draws a system's particles ([[particles]] draw): as the scene's geometry
// (its copies rasterised like any mesh), or as light-field billboards (particle_billboards.h),
// whose copies in the scene only the path tracer and the other renderers see.
struct ParticleDrawing {
  bool lightField = false;
  glm::ivec2 views{16, 8};  // the light field's azimuths x elevations
  int resolution = 64;      // texels per side of a view
  bool interpolate = true;  // blend the four views around the direction (false: the nearest)
  // The shadow maps blend too (else they take the nearest view: a shadow needs the silhouette's
  // depth alone, and one view costs a quarter of four; docs/particles.md measures both).
  bool interpolateShadows = false;
  // The particles are drawn into the RSMs (either drawing), so their surfaces are VPLs: they
  // reflect light into the grid. False leaves them out there (what is behind them injects as if
  // they were not there); they still cast shadows and block light in the geometry volume.
  bool inject = true;
};

class ParticleGeometry {
public:
  // Appends the model's materials (coloured by the system's colour unless it has colour keys)
  // and its meshes, with room for system.capacity() copies (and their vertex colours with colour
  // keys), to `scene`, and places the particles alive at `seconds`.
  // Throws an Error when the copies would exceed `maxTriangles`.
  ParticleGeometry(ParticleSystem system, const ParticleModel& model, Scene& scene,
                   double seconds, std::size_t maxTriangles, ParticleDrawing drawing = {});

  // Places the particles alive at `seconds` into the meshes this system appended to `scene`
  // (positions, normals and, with colour keys, colours); returns how many there are.
  std::size_t place(Scene& scene, double seconds) const;

  const ParticleSystem& system() const { return system_; }
  const ParticleModel& model() const { return model_; }
  const ParticleDrawing& drawing() const { return drawing_; }
  int firstMesh() const { return firstMesh_; }
  int meshCount() const { return int(model_.meshes.size()); }
  // Whether each particle's colour is its own (colour keys: in the copies' vertex colours).
  bool colouredPerParticle() const { return !system_.colorOverLife.empty(); }

private:
  ParticleSystem system_;
  ParticleModel model_;
  ParticleDrawing drawing_;
  int firstMesh_ = 0;
  std::vector<std::size_t> emitterSlot_;  // the first slot of each emitter
};

}  // namespace lpvlab
