#pragma once
// The scene uploaded for rasterisation: one interleaved vertex buffer and one index buffer for
// all meshes, sorted into one draw range per material, the materials in a storage buffer and each
// base colour texture as an sRGB, mip-mapped GL texture (where material.glsl reads them).

#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// Where scene.vert reads the vertices (the layout below) and the clip-from-world matrix that every
// pass rasterising the scene sets.
namespace scene_vertex {
#include "shaders/raster/scene_interface.glsl"
}

struct GpuMaterial {  // std430 mirror of shaders/raster/material.glsl
  glm::vec4 baseColorCutoff;
  glm::vec4 emissionTextured;
};

class SceneGpu {
public:
  explicit SceneGpu(const Scene& scene);
  ~SceneGpu();
  SceneGpu(const SceneGpu&) = delete;
  SceneGpu& operator=(const SceneGpu&) = delete;

  // Which materials' triangles draw() covers.
  enum class AlphaMasks { Any, Only, None };
  // Draws the selected triangles with the currently bound program; with `bindMaterials` it sets
  // uniform location 1 (materialIndex) and texture unit 0 per material (a depth-only program
  // for surfaces without alpha masks needs neither, and has no such uniform). `injectingOnly`
  // leaves out the materials that do not inject (Material::injects): the RSMs' draw.
  void draw(AlphaMasks which = AlphaMasks::Any, bool bindMaterials = true, bool injectingOnly = false) const;
  std::size_t memoryBytes() const;
  // Uploads the vertices of `scene` again: the same meshes, moved (an animation's rigid motions,
  // framework/animation/animation.h) or recoloured (a particle's colour over its life).
  // Throws if `scene` has other meshes than the uploaded one.
  void updateGeometry(const Scene& scene);
  // The scene's materials as given (for strategies that treat some materials apart, e.g. the
  // translucent ones of rendering "subsurface"), and the bounds of each one's triangles (empty
  // bounds for a material no mesh uses).
  const std::vector<Material>& materials() const { return sceneMaterials_; }
  const Bounds& materialBounds(int material) const { return materialBounds_.at(material); }

private:
  struct DrawRange {
    int material;
    bool alphaMasked;  // the material's alpha mask can cut fragments out
    bool injects;      // Material::injects
    std::size_t firstIndex;
    std::size_t indexCount;
  };
  void measureMaterialBounds(const Scene& scene);

  std::vector<int> meshOrder_;             // meshes grouped by material, the vertex buffer's order
  std::vector<std::size_t> vertexCounts_;  // per mesh, as uploaded
  GLuint vertexArray_ = 0;
  gl::Buffer vertices_, indices_, materials_;
  std::vector<gl::Texture> textures_;     // one per Scene::textures entry
  gl::Texture white_;                      // bound for untextured materials
  std::vector<int> textureOfMaterial_;
  std::vector<DrawRange> draws_;
  std::vector<Material> sceneMaterials_;
  std::vector<Bounds> materialBounds_;  // per material
};

}  // namespace lpvlab
