#include "framework/radiosity/hemicube.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/view_matrix.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

namespace hemicube_interface {
#include "shaders/radiosity/hemicube_interface.glsl"
}

struct HemicubeVertex {
  glm::vec3 position;
  std::uint32_t patch;
};

// A perspective frustum with reversed depth and no far plane: window depth = near / distance
// along the view (1 at the near plane, towards 0 far away), with GL's clip control set to depth
// in [0, 1]. A float depth buffer then resolves every distance to its own relative precision.
glm::mat4 reversedFrustum(float left, float right, float bottom, float top, float near) {
  glm::mat4 m(0.0f);
  m[0][0] = 2.0f * near / (right - left);
  m[1][1] = 2.0f * near / (top - bottom);
  m[2][0] = (right + left) / (right - left);
  m[2][1] = (top + bottom) / (top - bottom);
  m[2][3] = -1.0f;
  m[3][2] = near;
  return m;
}

// Raster state the item buffer needs, restored for the passes that assume GL's defaults.
class ReversedDepthState {
public:
  ReversedDepthState() {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDisable(GL_CULL_FACE);  // both sides are seen, told apart by gl_FrontFacing
  }
  ~ReversedDepthState() {
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(GL_LESS);
  }
  ReversedDepthState(const ReversedDepthState&) = delete;
  ReversedDepthState& operator=(const ReversedDepthState&) = delete;
};

}  // namespace

HemicubeFormFactors::HemicubeFormFactors(ShaderCompiler& shaders, const PatchMesh& mesh, int resolution,
                                         float sceneSize, HemicubePlacement placement, std::uint64_t seed)
    : mesh_(mesh), maps_(hemicubeMaps(resolution)), placement_(placement), seed_(seed) {
  if (mesh.patches.size() > (std::size_t(1) << 30))
    throw Error("radiosity: more patches than the hemicube's 32-bit item buffer can name");
  program_ = shaders.graphics("radiosity/hemicube.vert", "radiosity/hemicube.frag");
  std::vector<HemicubeVertex> vertices;
  vertices.reserve(3 * mesh.patches.size());
  for (std::size_t p = 0; p < mesh.patches.size(); ++p)
    for (const glm::vec3& corner : mesh.patches[p].corners) vertices.push_back({corner, std::uint32_t(p)});
  vertices_ = gl::Buffer(vertices.size() * sizeof(HemicubeVertex), "hemicube patches", vertices.data());
  glCreateVertexArrays(1, &vertexArray_);
  glVertexArrayVertexBuffer(vertexArray_, 0, vertices_.id(), 0, sizeof(HemicubeVertex));
  using namespace hemicube_interface;
  glEnableVertexArrayAttrib(vertexArray_, HEMICUBE_ATTRIBUTE_POSITION);
  glVertexArrayAttribFormat(vertexArray_, HEMICUBE_ATTRIBUTE_POSITION, 3, GL_FLOAT, GL_FALSE,
                            offsetof(HemicubeVertex, position));
  glVertexArrayAttribBinding(vertexArray_, HEMICUBE_ATTRIBUTE_POSITION, 0);
  glEnableVertexArrayAttrib(vertexArray_, HEMICUBE_ATTRIBUTE_PATCH);
  glVertexArrayAttribIFormat(vertexArray_, HEMICUBE_ATTRIBUTE_PATCH, 1, GL_UNSIGNED_INT,
                             offsetof(HemicubeVertex, patch));
  glVertexArrayAttribBinding(vertexArray_, HEMICUBE_ATTRIBUTE_PATCH, 0);

  // An atlas of tiles, each one hemicube: the top face (resolution^2) under the four half faces
  // (resolution x resolution/2 each), so a tile is resolution wide and 3 resolution high.
  tilesX_ = std::clamp(2048 / resolution, 1, 16);
  tilesY_ = std::clamp(6144 / (3 * resolution), 1, 16);
  const int width = tilesX_ * resolution, height = tilesY_ * 3 * resolution;
  items_ = gl::Texture(GL_TEXTURE_2D, GL_R32UI, width, height, 1, "hemicube item buffer");
  depth_ = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, "hemicube depth");
  framebuffer_.attach(GL_COLOR_ATTACHMENT0, items_);
  framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
  framebuffer_.checkComplete("hemicube atlas");
  readback_.resize(std::size_t(width) * std::size_t(height));
  near_ = std::max(1e-5f * sceneSize, 1e-20f);
  checkGl("hemicube setup");
}

HemicubeFormFactors::~HemicubeFormFactors() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void HemicubeFormFactors::viewsOf(std::uint32_t side, View* views) const {
  const Patch& patch = mesh_.patches[side / 2];
  const glm::vec3 n = sideNormal(mesh_, side);
  const auto inPlane = [&](const glm::vec3& v) { return glm::normalize(v - glm::dot(v, n) * n); };
  const glm::vec3 towardsCorner = inPlane(patch.corners[0] - patch.centroid);
  switch (placement_) {
    case HemicubePlacement::Centroid:
      views[0] = {patch.centroid, towardsCorner};
      return;
    case HemicubePlacement::Vertices:
      for (int c = 0; c < 3; ++c)
        views[c] = {glm::mix(patch.corners[c], patch.centroid, 0.01f), towardsCorner};
      return;
    case HemicubePlacement::Jittered: {
      SampleRandom random(seed_, side, 0);
      const float u = random.uniform(), v = random.uniform(), angle = float(2.0 * M_PI) * random.uniform();
      const float su = std::sqrt(u);  // uniform on the triangle (Turk's square-root map)
      const glm::vec3 eye = (1.0f - su) * patch.corners[0] + su * (1.0f - v) * patch.corners[1] +
                            su * v * patch.corners[2];
      const glm::vec3 b = glm::cross(n, towardsCorner);
      views[0] = {eye, std::cos(angle) * towardsCorner + std::sin(angle) * b};
      return;
    }
  }
}

void HemicubeFormFactors::renderBatch(const std::uint32_t* sides, std::size_t count) {
  const int res = maps_.resolution, half = res / 2;
  const std::uint32_t none = 0;
  const float far = 0.0f;  // reversed depth: 0 is infinitely far
  framebuffer_.bind();
  glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 0, &none);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far);
  ReversedDepthState state;
  program_.use();
  glBindVertexArray(vertexArray_);
  const GLint location = hemicube_interface::HEMICUBE_LOCATION_CLIP_FROM_WORLD;
  const GLsizei vertexCount = GLsizei(3 * mesh_.patches.size());
  const glm::mat4 topProjection = reversedFrustum(-near_, near_, -near_, near_, near_);
  const glm::mat4 sideProjection = reversedFrustum(-near_, near_, 0.0f, near_, near_);
  const int views = viewsPerSide();
  for (std::size_t k = 0; k < count; ++k) {
    View placed[3];
    viewsOf(sides[k], placed);
    const glm::vec3 n = sideNormal(mesh_, sides[k]);
    for (int v = 0; v < views; ++v) {
      const std::size_t tile = k * std::size_t(views) + std::size_t(v);
      const glm::vec3 eye = placed[v].eye;
      // The top view's "up" in the side's plane, the side views around it.
      const glm::vec3 t = placed[v].up;
      const glm::vec3 b = glm::cross(n, t);
      const int x0 = int(tile % std::size_t(tilesX_)) * res, y0 = int(tile / std::size_t(tilesX_)) * 3 * res;
      auto draw = [&](const glm::mat4& clipFromWorld, int y, int height) {
        glViewport(x0, y, res, height);
        glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(clipFromWorld));
        glDrawArrays(GL_TRIANGLES, 0, vertexCount);
      };
      draw(topProjection * viewFromWorld(eye, n, t), y0, res);
      const glm::vec3 across[4] = {t, -t, b, -b};
      for (int face = 0; face < 4; ++face)
        draw(sideProjection * viewFromWorld(eye, across[face], n), y0 + res + face * half, half);
    }
  }
  glBindVertexArray(0);
  glGetTextureImage(items_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    GLsizei(readback_.size() * sizeof(std::uint32_t)), readback_.data());
  checkGl("hemicube views");
  hemicubes_ += count * std::size_t(views);
}

void HemicubeFormFactors::computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) {
  const int res = maps_.resolution, half = res / 2;
  const std::size_t width = std::size_t(tilesX_) * std::size_t(res);
  tbb::enumerable_thread_specific<RowAccumulator> accumulators([&] { return RowAccumulator(mesh_.sides()); });
  for (std::size_t first = 0; first < sides.size(); first += batch()) {
    const std::size_t count = std::min(batch(), sides.size() - first);
    renderBatch(sides.data() + first, count);
    std::vector<std::vector<FormFactor>> made(count);
    const std::size_t views = std::size_t(viewsPerSide());
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t k) {
      RowAccumulator& row = accumulators.local();
      // A side's hemicubes fill consecutive tiles; its row is their mean.
      for (std::size_t tile = k * views; tile < (k + 1) * views; ++tile) {
        const std::size_t x0 = (tile % std::size_t(tilesX_)) * std::size_t(res);
        const std::size_t y0 = (tile / std::size_t(tilesX_)) * 3 * std::size_t(res);
        auto accumulate = [&](std::size_t y, std::size_t height, const std::vector<float>& delta) {
          for (std::size_t r = 0; r < height; ++r) {
            const std::uint32_t* line = readback_.data() + (y + r) * width + x0;
            const float* weights = delta.data() + r * std::size_t(res);
            for (int x = 0; x < res; ++x)
              if (line[x] != 0) row.add(line[x] - 1, weights[x]);
          }
        };
        accumulate(y0, std::size_t(res), maps_.top);
        for (int face = 0; face < 4; ++face)
          accumulate(y0 + std::size_t(res) + std::size_t(face * half), std::size_t(half), maps_.side);
      }
      made[k] = row.take(1.0 / double(views));
    });
    for (std::size_t k = 0; k < count; ++k) rows.set(sides[first + k], std::move(made[k]));
  }
}

nlohmann::json HemicubeFormFactors::statistics() const {
  const char* placement = placement_ == HemicubePlacement::Vertices   ? "vertices"
                          : placement_ == HemicubePlacement::Jittered ? "jittered"
                                                                      : "centroid";
  return {{"estimator", "hemicube"},
          {"resolution", maps_.resolution},
          {"placement", placement},
          {"hemicubes", hemicubes_},
          {"hemicubes_per_readback", batch()},
          {"delta_form_factor_raw_sum", maps_.rawSum},
          {"near_plane_m", near_}};
}

std::size_t HemicubeFormFactors::memoryBytes() const {
  return vertices_.size() + items_.bytes() + depth_.bytes() + readback_.size() * sizeof(std::uint32_t) +
         (maps_.top.size() + maps_.side.size()) * sizeof(float);
}

}  // namespace lpvlab
