#include "framework/raster/ray_raster.h"

#include <chrono>
#include <limits>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/raster/cast_view.h"
#include "framework/raster/view_rays.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/raster/gbuffer_texel.glsl"
#include "shaders/raster/rsm_texel.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

// The texture coordinates where `ray` meets the plane of the triangle with these corners: a
// neighbouring pixel's, for the derivatives GL takes between the pixels of a quad (the plane
// extends past the triangle, as GL's helper pixels do). Nothing for a ray along the plane.
std::optional<glm::vec2> uvOnPlane(const ViewRay& ray, const glm::vec3* p, const glm::vec2* uv) {
  const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const glm::vec3 n = glm::cross(e1, e2);
  const float along = glm::dot(n, ray.direction);
  if (!(std::abs(along) > 1e-20f)) return std::nullopt;
  const glm::vec3 d = ray.origin + (glm::dot(n, p[0] - ray.origin) / along) * ray.direction - p[0];
  const float d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const float d20 = glm::dot(d, e1), d21 = glm::dot(d, e2), den = d00 * d11 - d01 * d01;
  if (!(std::abs(den) > 0.0f)) return std::nullopt;
  const float b1 = (d11 * d20 - d01 * d21) / den, b2 = (d00 * d21 - d01 * d20) / den;
  return uv[0] + b1 * (uv[1] - uv[0]) + b2 * (uv[2] - uv[0]);
}

void checkLayers(const LightViews& views, int resolution, int width, int height, int layers,
                 const char* what) {
  if (width != resolution || height != resolution || layers < int(views.views.size()))
    throw Error(std::string("ray-cast raster: the ") + what + " image is " + std::to_string(width) +
                "x" + std::to_string(height) + " with " + std::to_string(layers) + " layers, not " +
                std::to_string(resolution) + "^2 with one per light view");
}

}  // namespace

RayRaster::RayRaster(const Scene& scene, const RayEngineSettings& engine)
    : scene_(scene), engine_(engine) {
  materials_ = prepareMaterials(scene_);
  for (const TextureImage& texture : scene_.textures) mips_.push_back(std::make_unique<MipChain>(texture));
  build();
}

RayRaster::TexelSurface RayRaster::surfaceOf(const EmbreeScene& scene, const ViewRays& rays, int x,
                                             int y, const ViewRay& ray, const RayHit& hit) const {
  const GeometryRecord& g = scene.geometry(hit.geomID);
  const std::uint32_t* corner = g.indices + 3 * std::size_t(hit.primID);
  TexelSurface s{ray.origin + hit.distance * ray.direction,
                 atBarycentrics(g.normals, corner, hit.u, hit.v), g.material->baseColor, &g};
  if (g.colors) s.albedo *= atBarycentrics(g.colors, corner, hit.u, hit.v);
  if (g.material->texture) s.albedo *= glm::vec3(textureAt(g, hit.primID, hit.u, hit.v, rays, x, y));
  return s;
}

glm::vec4 RayRaster::textureAt(const GeometryRecord& g, unsigned primID, float u, float v,
                               const ViewRays& rays, int x, int y) const {
  const TextureLookup t = lookupAt(g, primID, u, v, rays, x, y);
  return t.mips->sample(t.uv, t.lod);
}

RayRaster::TextureLookup RayRaster::lookupAt(const GeometryRecord& g, unsigned primID, float u,
                                             float v, const ViewRays& rays, int x, int y) const {
  const std::uint32_t* corner = g.indices + 3 * std::size_t(primID);
  const glm::vec2 uv = atBarycentrics(g.uvs, corner, u, v);
  const glm::vec3* positions = scene_.meshes[std::size_t(g.meshIndex)].positions.data();
  const glm::vec3 p[3] = {positions[corner[0]], positions[corner[1]], positions[corner[2]]};
  const glm::vec2 uvs[3] = {g.uvs[corner[0]], g.uvs[corner[1]], g.uvs[corner[2]]};
  const std::optional<glm::vec2> right = uvOnPlane(rays.ray(x + 1, y), p, uvs);
  const std::optional<glm::vec2> up = uvOnPlane(rays.ray(x, y + 1), p, uvs);
  const MipChain& mips = *mips_[std::size_t(g.material->texture - scene_.textures.data())];
  return {&mips, uv, right && up ? mips.lodOf(*right - uv, *up - uv) : 0.0f};
}

class RayRaster::ViewAlpha final : public AlphaLookup {
public:
  ViewAlpha(const RayRaster& raster, const ViewRays& rays) : raster_(raster), rays_(rays) {}
  float alpha(const GeometryRecord& g, unsigned primID, float u, float v, unsigned rayId) const override {
    const int x = int(rayId % unsigned(rays_.width())), y = int(rayId / unsigned(rays_.width()));
    const TextureLookup t = raster_.lookupAt(g, primID, u, v, rays_, x, y);
    return t.mips->sampleAlpha(t.uv, t.lod);
  }

private:
  const RayRaster& raster_;
  const ViewRays& rays_;
};

void RayRaster::build() {
  const auto start = std::chrono::steady_clock::now();
  const auto drawn = [](const Mesh& mesh) { return mesh.rasterised; };
  drawn_ = std::make_unique<EmbreeScene>(scene_, materials_, engine_, drawn);
  const auto injects = [this](const Mesh& mesh) {
    return mesh.rasterised && scene_.materials[std::size_t(mesh.material)].injects;
  };
  std::size_t injectingTriangles = 0, drawnTriangles = 0;
  for (const Mesh& mesh : scene_.meshes) {
    if (drawn(mesh)) drawnTriangles += mesh.indices.size() / 3;
    if (injects(mesh)) injectingTriangles += mesh.indices.size() / 3;
  }
  injecting_.reset();
  if (injectingTriangles == drawnTriangles) {
    rsmScene_ = drawn_.get();
  } else if (injectingTriangles > 0) {
    injecting_ = std::make_unique<EmbreeScene>(scene_, materials_, engine_, injects);
    rsmScene_ = injecting_.get();
  } else {
    rsmScene_ = nullptr;
  }
  buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::json RayRaster::report() const {
  return {{"name", name()},
          {"isa", drawn_->isa()},
          {"packet_width", drawn_->packetWidth()},
          {"bvh_build_ms", buildMs_},
          {"texture_filtering", "trilinear mip-mapped (texture_mips.h); alpha masks at level 0"}};
}

void RayRaster::renderGBuffer(const Camera& camera, const glm::mat4& clipFromWorld,
                              const HostGBufferTargets& out) {
  const ViewRays rays(clipFromWorld, out.position->width, out.position->height);
  for (HostImage* image : {out.position, out.normal, out.albedo, out.emission})
    if (image && (image->width != rays.width() || image->height != rays.height()))
      throw Error("ray-cast raster: the G-buffer's images differ in size");
  const glm::vec3 eye = camera.position, forward = camera.forward;
  const ViewAlpha alpha(*this, rays);
  castView(*drawn_, rays, &alpha, [&](int x, int y, const ViewRay& ray, const RayHit* hit) {
    const std::size_t i = std::size_t(y) * rays.width() + x;
    if (!hit) {  // GL clears every target to zeros
      out.position->texels[i] = out.normal->texels[i] = out.albedo->texels[i] = glm::vec4(0.0f);
      if (out.emission) out.emission->texels[i] = glm::vec4(0.0f);
      return;
    }
    const TexelSurface s = surfaceOf(*drawn_, rays, x, y, ray, *hit);
    const shared::GBufferTexel texel = shared::gbufferTexel(s.position, s.normal, eye, forward);
    out.position->texels[i] = texel.position;
    out.normal->texels[i] = texel.normal;
    out.albedo->texels[i] = glm::vec4(s.albedo, 1.0f);
    if (out.emission) out.emission->texels[i] = glm::vec4(s.geometry->material->emission, 1.0f);
  });
}

void RayRaster::renderShadowMaps(const LightViews& views, int resolution, HostDepthImage& out) {
  checkLayers(views, resolution, out.width, out.height, out.layers, "shadow map");
  for (std::size_t v = 0; v < views.views.size(); ++v) {
    const ViewRays rays(views.views[v].clipFromWorld, resolution, resolution);
    float* layer = out.depths.data() + v * std::size_t(resolution) * resolution;
    const ViewAlpha alpha(*this, rays);
    castView(*drawn_, rays, &alpha, [&](int x, int y, const ViewRay& ray, const RayHit* hit) {
      layer[std::size_t(y) * resolution + x] =
          hit ? rays.windowDepth(ray.origin + hit->distance * ray.direction) : 1.0f;
    });
  }
}

void RayRaster::renderRsms(const LightViews& views, int resolution, const HostRsmTargets& out) {
  for (HostImage* image : {out.position, out.normal, out.flux})
    checkLayers(views, resolution, image->width, image->height, image->layers, "RSM");
  const auto shared = sharedLightViews<shared::GpuLight, shared::GpuView>(views);
  for (std::size_t v = 0; v < views.views.size(); ++v) {
    const std::size_t offset = v * std::size_t(resolution) * resolution;
    if (!rsmScene_) {  // nothing injects: GL draws nothing into the cleared maps
      for (HostImage* image : {out.position, out.normal, out.flux})
        std::fill_n(image->texels.begin() + std::ptrdiff_t(offset), std::size_t(resolution) * resolution,
                    glm::vec4(0.0f));
      continue;
    }
    const ViewRays rays(views.views[v].clipFromWorld, resolution, resolution);
    const shared::GpuView& view = shared.views[v];
    const shared::GpuLight& light = shared.lights[std::size_t(view.params.z)];
    const ViewAlpha alpha(*this, rays);
    castView(*rsmScene_, rays, &alpha, [&](int x, int y, const ViewRay& ray, const RayHit* hit) {
      const std::size_t i = offset + std::size_t(y) * resolution + x;
      if (!hit) {
        out.position->texels[i] = out.normal->texels[i] = out.flux->texels[i] = glm::vec4(0.0f);
        return;
      }
      const TexelSurface s = surfaceOf(*rsmScene_, rays, x, y, ray, *hit);
      const shared::RsmTexelLight arriving = shared::rsmTexelLight(
          view, light, s.position, s.normal, glm::vec2(x + 0.5f, y + 0.5f), resolution);
      out.position->texels[i] = glm::vec4(s.position, 1.0f);
      out.normal->texels[i] = glm::vec4(arriving.normal, 0.0f);
      out.flux->texels[i] = glm::vec4(s.albedo * arriving.flux, 1.0f);
    });
  }
}

void RayRaster::shadowRays(const HostImage& position, const HostImage& normal,
                           const LightViews& views, std::vector<float>& visibility) {
  const std::size_t pixels = position.texels.size(), lights = views.lights.size();
  if (normal.texels.size() != pixels) throw Error("shadow rays: the G-buffer's images differ in size");
  visibility.assign(pixels * lights, 0.0f);
  const float epsilon = drawn_->epsilon();
  const std::size_t packets = (pixels + kPacketWidth - 1) / kPacketWidth;
  for (std::size_t l = 0; l < lights; ++l) {
    const GpuLight& light = views.lights[l];
    const bool directional = int(light.positionType.w) == shared::LIGHT_DIRECTIONAL;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, packets), [&](const tbb::blocked_range<std::size_t>& r) {
      ShadowPacket packet;
      for (std::size_t first = r.begin() * kPacketWidth; first < r.end() * kPacketWidth; first += kPacketWidth) {
        packet.clear();
        for (int lane = 0; lane < kPacketWidth && first + lane < pixels; ++lane) {
          const glm::vec4 p = position.texels[first + lane];
          if (p.w == 0.0f) continue;
          const glm::vec3 n(normal.texels[first + lane]);
          glm::vec3 toLight = -glm::vec3(light.directionCosOuter);
          float distance = std::numeric_limits<float>::infinity();
          if (!directional) {
            const glm::vec3 d = glm::vec3(light.positionType) - glm::vec3(p);
            distance = glm::length(d);
            toLight = d / distance;
          }
          if (!(glm::dot(n, toLight) > 0.0f) || !(distance > 2.0f * epsilon)) continue;
          packet.set(lane, glm::vec3(p) + epsilon * n, toLight, 0.0f, distance - epsilon);
        }
        drawn_->occluded(packet);
        for (int lane = 0; lane < kPacketWidth; ++lane)
          if (packet.valid[lane] && !packet.occluded(lane)) visibility[(first + lane) * lights + l] = 1.0f;
      }
    });
  }
}

void RayRaster::moveGeometry(const Scene& scene) {
  if (scene.meshes.size() != scene_.meshes.size())
    throw Error("ray-cast raster: the scene's meshes changed in number (only moves are followed)");
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    if (scene.meshes[m].positions.size() != scene_.meshes[m].positions.size())
      throw Error("ray-cast raster: mesh '" + scene.meshes[m].name + "' changed its vertex count");
    scene_.meshes[m].positions = scene.meshes[m].positions;
    scene_.meshes[m].normals = scene.meshes[m].normals;
  }
  build();
}

std::size_t RayRaster::memoryBytes() const {
  std::size_t bytes = 0;
  for (const Mesh& mesh : scene_.meshes)
    bytes += mesh.positions.size() * (2 * sizeof(glm::vec3) + sizeof(glm::vec2)) +
             mesh.colors.size() * sizeof(glm::vec3) + mesh.indices.size() * sizeof(std::uint32_t);
  for (const TextureImage& texture : scene_.textures) bytes += texture.rgba8.size();
  for (const auto& mips : mips_) bytes += mips->bytes();
  return bytes;
}

}  // namespace lpvlab
