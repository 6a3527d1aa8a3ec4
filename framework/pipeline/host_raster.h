#pragma once
// Raster passes that make the raster inputs' images on the host instead of on GL
// ([compute] raster; framework/raster: by casting one ray through each texel centre with
// Embree). The pipeline owns one when the run chose it for some pass (RasterPlan): each frame it
// writes that pass's images (the G-buffer, the shadow maps, the RSMs) into the frame's host images
// (HostReadback::written), which CPU kernels read as they read GL's images read back. The images
// are those the GL passes make, up to which triangle covers a pixel that a triangle edge crosses:
// texel centres, the same depth test (nearest), the same fragment arithmetic (shared GLSL), bottom
// row first. It also traces exact shadow rays for direct light ([light_maps] shadows = "rays").

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/light_views.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// The camera's G-buffer on the host, each image width x height, RGBA as GBuffer's textures.
struct HostGBufferTargets {
  HostImage* position = nullptr;
  HostImage* normal = nullptr;
  HostImage* albedo = nullptr;
  HostImage* emission = nullptr;  // null: no material emits (GL's stays zeros)
};

// Every light view's RSM on the host, one layer per view, resolution^2 texels each.
struct HostRsmTargets {
  HostImage* position = nullptr;
  HostImage* normal = nullptr;
  HostImage* flux = nullptr;
};

class HostRaster {
public:
  virtual ~HostRaster() = default;

  // "embree": what the manifest's compute report names.
  virtual std::string name() const = 0;
  // How it runs (instruction set, packet width, scene build time): the compute report's entry.
  virtual nlohmann::json report() const = 0;

  // gbuffer.frag's images from `camera`, whose view and projection are clipFromWorld.
  virtual void renderGBuffer(const Camera& camera, const glm::mat4& clipFromWorld,
                             const HostGBufferTargets& out) = 0;
  // Every view's shadow map: the window depth (0 near .. 1 far) of the nearest surface, 1 where
  // none; alpha-masked surfaces cut out.
  virtual void renderShadowMaps(const LightViews& views, int resolution, HostDepthImage& out) = 0;
  // Every view's RSM (rsm.frag): position, normal facing the light, reflected flux.
  virtual void renderRsms(const LightViews& views, int resolution, const HostRsmTargets& out) = 0;
  // Per G-buffer pixel and light, whether the way from the pixel's surface (position, normal
  // facing the camera: the G-buffer's) to the light is open: visibility[pixel * lights + light]
  // is 1 or 0 (0 where no surface was hit). Alpha masks let light through where they cut out.
  virtual void shadowRays(const HostImage& position, const HostImage& normal,
                          const LightViews& views, std::vector<float>& visibility) = 0;
  // The scene's meshes moved (Pipeline::moveScene): `scene` has the same meshes, moved.
  virtual void moveGeometry(const Scene& scene) = 0;
  // Host bytes it holds (its copy of the scene), for the memory report.
  virtual std::size_t memoryBytes() const = 0;
};

// The names of the raster passes (Pipeline::stageNames' first three).
inline constexpr const char* kShadowMapPass = "shadow_maps";
inline constexpr const char* kRsmPass = "rsm";
inline constexpr const char* kGBufferPass = "gbuffer";

// Where a run's raster passes run (framework/raster/raster_choice.h makes it).
struct RasterPlan {
  std::unique_ptr<HostRaster> host;  // null: every pass on GL, and no shadow rays
  std::set<std::string> hostPasses;  // the passes `host` renders (kShadowMapPass, ...)
  // Why, as the manifest's compute report has it beside where each pass ran (an object: the
  // request, the model's estimates).
  nlohmann::json record = nlohmann::json::object();
};

}  // namespace lpvlab
