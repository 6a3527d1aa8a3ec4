// The raster passes by ray casting (framework/raster/ray_raster.h) against GL's on llvmpipe, pass
// by pass (the G-buffer, every light view's shadow map and RSM), on the Cornell box (a spot light:
// cube faces), Sibenik's lamp (a point light: six faces) and Sponza under the sun (an
// orthographic view; alpha-masked foliage and textures): in at least 99% of texels the two give
// the same surface (coverage, position, normal, albedo, depth, flux, within float rounding and
// GL's subpixel snapping), and every texel where they differ is at an edge: a 4 x 4 grid of rays
// across the texel does not all meet the same triangle (an edge, or an alpha mask's cut-out
// border, crosses it, and which side covers the texel centre is the rasteriser's tie-break).
// Textures: both sample a mip chain trilinearly at the level of detail of the texel's footprint,
// but GL implementations approximate that level (llvmpipe per 2 x 2 quad) and round their mip
// levels their own way, so textured albedo and flux differ in the blend: those texels are
// counted apart, and held to a few percent per texel (median, 99th percentile) and on average.
// The geometry of a textured texel (coverage, position, normal) must still be equal; alpha masks
// are tested at the same level of detail as GL's, so foliage covers the same texels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "framework/raster/ray_raster.h"
#include "framework/raster/view_rays.h"
#include "framework/reference/embree_scene.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

std::string experimentFile(const std::string& name) {
  return name.empty() ? "" : std::string(LPVLAB_SOURCE_DIR "/experiments/") + name;
}

// Which triangle a ray through image position (px, py) meets first: (geomID, primID), or
// (-1, -1) for none.
std::pair<long, long> triangleAt(const EmbreeScene& scene, const ViewRays& rays, float px, float py) {
  const ViewRay ray = rays.rayAt(px, py);
  RayPacket packet;
  packet.set(0, ray.origin, ray.direction, 0.0f, ray.length);
  scene.intersect(packet, false);
  if (!packet.hit(0)) return {-1, -1};
  const RayHit hit = packet.hitAt(0);
  return {long(hit.geomID), long(hit.primID)};
}

// Whether an edge crosses texel (x, y): a 4 x 4 grid of rays across it meets more than one
// triangle (or some meet none).
bool edgeInTexel(const EmbreeScene& scene, const ViewRays& rays, int x, int y) {
  const auto first = triangleAt(scene, rays, x + 0.05f, y + 0.05f);
  for (float dy : {0.05f, 0.35f, 0.65f, 0.95f})
    for (float dx : {0.05f, 0.35f, 0.65f, 0.95f})
      if (triangleAt(scene, rays, x + dx, y + dy) != first) return true;
  return false;
}

// The metres one texel spans at distance `along` its ray: GL snaps vertices to 1/256 of a pixel,
// which moves where a pixel centre lands on the triangle by about that much.
float texelFootprint(const ViewRays& rays, int x, int y, glm::vec3 point) {
  const ViewRay here = rays.ray(x, y), next = rays.rayAt(x + 1.5f, y + 0.5f);
  const float t = glm::dot(point - here.origin, here.direction);
  return glm::length((next.origin + t * next.direction) - (here.origin + t * here.direction));
}

struct PassTally {
  std::size_t texels = 0, equal = 0, edge = 0, offEdge = 0, textured = 0;
  double texturedSum = 0.0, texturedDifference = 0.0;  // of the textured texels' values
  std::vector<float> texturedRelative;                // |ray - GL| / GL of each, summed over RGB
  float texturedQuantile(double q) const {
    if (texturedRelative.empty()) return 0.0f;
    std::vector<float> sorted = texturedRelative;
    std::sort(sorted.begin(), sorted.end());
    return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())))];
  }
};

void report(const std::string& what, const PassTally& t) {
  std::cout << "[ raster ] " << what << ": " << t.texels << " texels, "
            << 100.0 * double(t.equal) / double(t.texels) << "% equal, " << t.edge
            << " differ at an edge, " << t.offEdge << " elsewhere; " << t.textured
            << " differ by texture filtering alone (mean "
            << (t.texturedSum > 0.0 ? t.texturedDifference / t.texturedSum : 0.0)
            << " of their mean; median " << t.texturedQuantile(0.5) << ", 99th percentile "
            << t.texturedQuantile(0.99) << " of the texel)\n";
}

void expectEdgeSampling(const std::string& what, const PassTally& t) {
  report(what, t);
  EXPECT_GE(double(t.equal + t.textured), 0.99 * double(t.texels)) << what;
  EXPECT_EQ(t.offEdge, 0u) << what << ": texels that differ away from any edge";
  // Filtering differs in the last bits of a blend (how rho is approximated, how mip levels are
  // rounded), never by a level: a few percent per texel, and not on average.
  if (t.textured > 0) {
    EXPECT_LT(std::abs(t.texturedDifference) / t.texturedSum, 0.03) << what;
    EXPECT_LT(t.texturedQuantile(0.5), 0.03) << what;
    EXPECT_LT(t.texturedQuantile(0.99), 0.15) << what;
  }
}

// One texel of both passes: the geometry (coverage, position, normal) must agree within
// rounding; `value` (albedo or flux) too unless the surface is textured, where filtering may
// differ.
struct TexelPair {
  glm::vec4 glPosition, rayPosition, glNormal, rayNormal, glValue, rayValue;
};

void tallyTexel(PassTally& t, const TexelPair& p, float footprint, bool textured, bool edge) {
  ++t.texels;
  const bool sameCoverage = (p.glPosition.w > 0.0f) == (p.rayPosition.w > 0.0f);
  bool sameGeometry = sameCoverage;
  if (sameCoverage && p.glPosition.w > 0.0f) {
    sameGeometry = glm::length(glm::vec3(p.glPosition - p.rayPosition)) <= 0.05f * footprint + 1e-5f &&
                   glm::length(glm::vec3(p.glNormal - p.rayNormal)) <= 2e-3f;
  }
  const glm::vec3 scale = glm::max(glm::abs(glm::vec3(p.glValue)), glm::vec3(1e-6f));
  const bool sameValue = glm::all(glm::lessThanEqual(glm::abs(glm::vec3(p.glValue - p.rayValue)),
                                                     2e-3f * scale + 1e-7f));
  if (!sameGeometry) {
    ++(edge ? t.edge : t.offEdge);
  } else if (sameValue) {
    ++t.equal;
  } else if (textured) {
    ++t.textured;
    const float gl = p.glValue.r + p.glValue.g + p.glValue.b, ray = p.rayValue.r + p.rayValue.g + p.rayValue.b;
    t.texturedSum += gl;
    t.texturedDifference += ray - gl;
    t.texturedRelative.push_back(std::abs(ray - gl) / std::max(gl, 1e-6f));
  } else {
    ++t.offEdge;  // the same surface, untextured, and yet another value
  }
}

// Whether the surface a ray-cast texel sees is textured (its material has a texture).
bool texturedAt(const EmbreeScene& scene, const ViewRays& rays, int x, int y) {
  const ViewRay ray = rays.ray(x, y);
  RayPacket packet;
  packet.set(0, ray.origin, ray.direction, 0.0f, ray.length);
  scene.intersect(packet, false);
  return packet.hit(0) && scene.geometry(packet.hitAt(0).geomID).material->texture;
}

// One colour pass's texels (the G-buffer, or one light view's RSM) in both: position, normal and
// `value` (albedo or flux) images, texels [offset, offset + width * height) of each.
struct PassImages {
  const HostImage *position, *normal, *value;
};

void tallyPass(PassTally& t, const EmbreeScene& traced, const ViewRays& rays, const PassImages& gl,
               const PassImages& ray, std::size_t offset) {
  for (int y = 0; y < rays.height(); ++y)
    for (int x = 0; x < rays.width(); ++x) {
      const std::size_t i = offset + std::size_t(y) * rays.width() + x;
      const TexelPair p{gl.position->texels[i], ray.position->texels[i], gl.normal->texels[i],
                        ray.normal->texels[i],  gl.value->texels[i],     ray.value->texels[i]};
      const bool differs = p.glPosition != p.rayPosition || p.glValue != p.rayValue;
      tallyTexel(t, p, texelFootprint(rays, x, y, glm::vec3(p.glPosition)),
                 texturedAt(traced, rays, x, y), differs && edgeInTexel(traced, rays, x, y));
    }
}

struct Scenario {
  std::string file;  // experiments/<file>, "" the built-in Cornell box
  std::string what;
};

class RayRasterPasses : public ::testing::TestWithParam<Scenario> {};

TEST_P(RayRasterPasses, EqualGlsUpToEdgeSampling) {
  test::glTestContext();
  const Scenario& s = GetParam();
  Experiment e = loadExperiment(experimentFile(s.file),
                                {"output.width=240", "output.height=135",
                                 "light_maps.rsm_resolution=96", "light_maps.shadow_resolution=256"});
  const Scene& scene = e.scene;
  const bool emissive = false;
  ShaderCompiler shaders;
  SceneGpu sceneGpu(scene);
  GBufferPass gbufferPass(shaders, e.settings.width, e.settings.height, emissive);
  gbufferPass.render(sceneGpu, e.camera);
  const LightViews views =
      buildLightViews(scene.lights, scene.bounds(), directionalFollow(e.settings, e.camera));
  LightMapsPass mapsPass(shaders, views, e.settings.rsmResolution, e.settings.shadowResolution);
  mapsPass.renderShadowMaps(sceneGpu);
  mapsPass.renderRsms(sceneGpu);
  glFinish();

  HostReadback gl, rays;
  const GBuffer& g = gbufferPass.gbuffer();
  const LightMaps& maps = mapsPass.lightMaps();
  RayRaster raster(scene);
  raster.renderGBuffer(e.camera, gbufferPass.clipFromWorld(e.camera),
                       {.position = &rays.written(g.position), .normal = &rays.written(g.normal),
                        .albedo = &rays.written(g.albedo)});
  raster.renderShadowMaps(views, e.settings.shadowResolution, rays.writtenDepth(maps.shadowDepth));
  raster.renderRsms(views, e.settings.rsmResolution,
                    {.position = &rays.written(maps.rsmPosition), .normal = &rays.written(maps.rsmNormal),
                     .flux = &rays.written(maps.rsmFlux)});

  const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
  const EmbreeScene traced(scene, materials, {}, [](const Mesh& m) { return m.rasterised; });

  // The G-buffer: position, normal (w: view depth), albedo.
  {
    const ViewRays camera(gbufferPass.clipFromWorld(e.camera), g.width, g.height);
    PassTally t;
    tallyPass(t, traced, camera, {&gl.image(g.position), &gl.image(g.normal), &gl.image(g.albedo)},
              {&rays.image(g.position), &rays.image(g.normal), &rays.image(g.albedo)}, 0);
    expectEdgeSampling(s.what + ", G-buffer", t);
  }
  // Every view's shadow map (depth) and RSM (position, normal, flux).
  PassTally shadowTally, rsmTally;
  for (int v = 0; v < maps.views; ++v) {
    const ViewRays shadow(views.views[std::size_t(v)].clipFromWorld, maps.shadowResolution, maps.shadowResolution);
    const std::size_t shadowTexels = std::size_t(maps.shadowResolution) * maps.shadowResolution;
    for (int y = 0; y < maps.shadowResolution; ++y)
      for (int x = 0; x < maps.shadowResolution; ++x) {
        const std::size_t i = std::size_t(v) * shadowTexels + std::size_t(y) * maps.shadowResolution + x;
        const float a = gl.depth(maps.shadowDepth).depths[i], b = rays.depth(maps.shadowDepth).depths[i];
        ++shadowTally.texels;
        if (std::abs(a - b) <= 1e-5f + 1e-4f * (1.0f - a)) ++shadowTally.equal;
        else if (edgeInTexel(traced, shadow, x, y)) ++shadowTally.edge;
        else ++shadowTally.offEdge;
      }
    const int r = maps.rsmResolution;
    const ViewRays rsm(views.views[std::size_t(v)].clipFromWorld, r, r);
    tallyPass(rsmTally, traced, rsm,
              {&gl.image(maps.rsmPosition), &gl.image(maps.rsmNormal), &gl.image(maps.rsmFlux)},
              {&rays.image(maps.rsmPosition), &rays.image(maps.rsmNormal), &rays.image(maps.rsmFlux)},
              std::size_t(v) * r * r);
  }
  expectEdgeSampling(s.what + ", shadow maps (" + std::to_string(maps.views) + " views)", shadowTally);
  expectEdgeSampling(s.what + ", RSMs", rsmTally);
}

INSTANTIATE_TEST_SUITE_P(Scenes, RayRasterPasses,
                         ::testing::Values(Scenario{"", "Cornell box, spot light"},
                                           Scenario{"sibenik_lamp.toml", "Sibenik, point light"},
                                           Scenario{"sponza_sun.toml", "Sponza, sun"}),
                         [](const auto& info) {
                           return std::string(info.param.file.empty() ? "CornellBox"
                                              : info.param.file[1] == 'i' ? "SibenikLamp"
                                                                          : "SponzaSun");
                         });

}  // namespace
}  // namespace lpvlab
