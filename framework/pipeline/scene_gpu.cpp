#include "framework/pipeline/scene_gpu.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/gl/context.h"

namespace lpvlab {

namespace material_kernel {
#include "shaders/raster/material_interface.glsl"
}

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec3 color;  // Mesh::colors, white for a mesh without
};

gl::Texture uploadTexture(const TextureImage& source) {
  const int levels =
      1 + int(std::floor(std::log2(double(std::max(source.width, source.height)))));
  gl::Texture texture(GL_TEXTURE_2D, GL_SRGB8_ALPHA8, source.width, source.height, 1, source.path,
                  levels);
  glTextureSubImage2D(texture.id(), 0, 0, 0, source.width, source.height, GL_RGBA,
                      GL_UNSIGNED_BYTE, source.rgba8.data());
  glGenerateTextureMipmap(texture.id());
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return texture;
}

// The vertices of every mesh, interleaved, in `order`.
std::vector<Vertex> interleavedVertices(const Scene& scene, const std::vector<int>& order) {
  std::vector<Vertex> vertices;
  for (int meshIndex : order) {
    const Mesh& mesh = scene.meshes[std::size_t(meshIndex)];
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      vertices.push_back({mesh.positions[v], mesh.normals[v],
                          v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f),
                          v < mesh.colors.size() ? mesh.colors[v] : glm::vec3(1.0f)});
  }
  return vertices;
}

}  // namespace

void SceneGpu::measureMaterialBounds(const Scene& scene) {
  materialBounds_.assign(scene.materials.size(), Bounds{});
  for (const Mesh& mesh : scene.meshes)
    if (mesh.material >= 0 && mesh.material < int(materialBounds_.size()))
      for (std::uint32_t index : mesh.indices) materialBounds_[mesh.material].extend(mesh.positions[index]);
}

SceneGpu::SceneGpu(const Scene& scene) : sceneMaterials_(scene.materials) {
  measureMaterialBounds(scene);
  // Group meshes by material so each material is one draw call; meshes drawn by something else
  // (Mesh::rasterised) are left out.
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (scene.meshes[i].rasterised) meshOrder_.push_back(int(i));
  std::stable_sort(meshOrder_.begin(), meshOrder_.end(), [&](int a, int b) {
    return scene.meshes[a].material < scene.meshes[b].material;
  });
  std::vector<Vertex> vertices = interleavedVertices(scene, meshOrder_);
  if (vertices.empty()) vertices.push_back({});  // GL buffers are not empty; nothing draws it
  std::vector<std::uint32_t> indices;
  std::uint32_t base = 0;
  for (int meshIndex : meshOrder_) {
    const Mesh& mesh = scene.meshes[meshIndex];
    const std::size_t first = indices.size();
    for (std::uint32_t index : mesh.indices) indices.push_back(base + index);
    base += static_cast<std::uint32_t>(mesh.positions.size());
    if (!draws_.empty() && draws_.back().material == mesh.material)
      draws_.back().indexCount += mesh.indices.size();
    else {
      const bool known = mesh.material >= 0 && mesh.material < int(scene.materials.size());
      const Material* material = known ? &scene.materials[std::size_t(mesh.material)] : nullptr;
      draws_.push_back({mesh.material, material && material->alphaMode == AlphaMode::Mask,
                        !material || material->injects, first, mesh.indices.size()});
    }
  }
  for (const Mesh& mesh : scene.meshes) vertexCounts_.push_back(mesh.positions.size());
  if (!GlContext::glLoaded()) return;  // no GL (gl.backend = "none"): nothing to upload; draw() says so
  if (indices.empty()) indices.push_back(0);
  vertices_ = gl::Buffer(vertices.size() * sizeof(Vertex), "scene vertices", vertices.data());
  indices_ = gl::Buffer(indices.size() * sizeof(std::uint32_t), "scene indices", indices.data());

  std::vector<GpuMaterial> materials;
  for (const Material& m : scene.materials) {
    const float cutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : -1.0f;
    materials.push_back({glm::vec4(m.baseColor, cutoff),
                         glm::vec4(m.emission, m.baseColorTexture >= 0 ? 1.0f : 0.0f)});
    textureOfMaterial_.push_back(m.baseColorTexture);
  }
  if (materials.empty()) materials.push_back({glm::vec4(0.8f, 0.8f, 0.8f, -1.0f), glm::vec4(0.0f)});
  materials_ = gl::Buffer(materials.size() * sizeof(GpuMaterial), "scene materials", materials.data());

  for (const TextureImage& t : scene.textures) textures_.push_back(uploadTexture(t));
  white_ = gl::Texture(GL_TEXTURE_2D, GL_RGBA8, 1, 1, 1, "white");
  const std::uint8_t white[4] = {255, 255, 255, 255};
  glTextureSubImage2D(white_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);

  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayVertexBuffer(vertexArray_, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vertexArray_, indices_.id());
  struct Attribute {
    int location;  // scene.vert's
    GLint size;
    GLuint offset;
  };
  for (const Attribute& a : {Attribute{scene_vertex::ATTRIBUTE_POSITION, 3, offsetof(Vertex, position)},
                             Attribute{scene_vertex::ATTRIBUTE_NORMAL, 3, offsetof(Vertex, normal)},
                             Attribute{scene_vertex::ATTRIBUTE_UV, 2, offsetof(Vertex, uv)},
                             Attribute{scene_vertex::ATTRIBUTE_COLOR, 3, offsetof(Vertex, color)}}) {
    glEnableVertexArrayAttrib(vertexArray_, GLuint(a.location));
    glVertexArrayAttribFormat(vertexArray_, GLuint(a.location), a.size, GL_FLOAT, GL_FALSE, a.offset);
    glVertexArrayAttribBinding(vertexArray_, GLuint(a.location), 0);
  }
}

SceneGpu::~SceneGpu() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void SceneGpu::draw(AlphaMasks which, bool bindMaterials, bool injectingOnly) const {
  if (!vertexArray_) gl::noGl("drawing the scene");
  glBindVertexArray(vertexArray_);
  if (bindMaterials) materials_.bindStorage(material_kernel::BUFFER_MATERIALS);
  for (const DrawRange& range : draws_) {
    if ((which == AlphaMasks::Only && !range.alphaMasked) ||
        (which == AlphaMasks::None && range.alphaMasked) || (injectingOnly && !range.injects))
      continue;
    if (bindMaterials) {
      glUniform1i(material_kernel::LOCATION_MATERIAL_INDEX, range.material);
      const int texture = range.material < int(textureOfMaterial_.size())
                              ? textureOfMaterial_[range.material] : -1;
      glBindTextureUnit(material_kernel::UNIT_BASE_COLOR_TEXTURE, texture >= 0 ? textures_[texture].id() : white_.id());
    }
    glDrawElements(GL_TRIANGLES, GLsizei(range.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)));
  }
  glBindVertexArray(0);
}

void SceneGpu::updateGeometry(const Scene& scene) {
  bool same = scene.meshes.size() == vertexCounts_.size();
  for (std::size_t i = 0; same && i < vertexCounts_.size(); ++i)
    same = scene.meshes[i].positions.size() == vertexCounts_[i] &&
           scene.meshes[i].normals.size() == vertexCounts_[i];
  if (!same)
    throw Error("scene update: the meshes differ from the uploaded ones (only moves and colours are updated)");
  measureMaterialBounds(scene);
  if (!vertexArray_) return;  // no GL: nothing uploaded
  const std::vector<Vertex> vertices = interleavedVertices(scene, meshOrder_);
  vertices_.upload(vertices.data(), vertices.size() * sizeof(Vertex));
}

std::size_t SceneGpu::memoryBytes() const {
  std::size_t bytes = vertices_.size() + indices_.size() + materials_.size();
  for (const gl::Texture& t : textures_) bytes += t.bytes() * 4 / 3;  // with mip chain
  return bytes;
}

}  // namespace lpvlab
