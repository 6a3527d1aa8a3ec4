#pragma once
// The solution shown per pixel (seed 004, 3.8): each pixel of the G-buffer finds the patch side
// it sees (an Embree ray from the camera to its surface point) and reads that side's irradiance
//   flat      constant over the patch (the solution as solved)
//   gouraud   interpolated over the patch from its corners (barycentrics of the hit), a corner's
//             value the area-weighted mean of the sides that share its welded vertex and face
//             within 30 degrees of its own (a crease, such as a room's corner, is not smoothed)
// and shows albedo H / pi, W/(m^2 sr): a Lambertian surface's outgoing radiance under
// irradiance H, with the pixel's own (textured) albedo, as every indirect method's image is.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "framework/pipeline/host_readback.h"
#include "framework/radiosity/patch_ray_scene.h"
#include "framework/radiosity/patches.h"
#include "framework/scene/scene.h"

namespace lpvlab {

enum class PatchInterpolation { Flat, Gouraud };

class PatchDisplay {
public:
  PatchDisplay(const PatchMesh& mesh, const PatchRayScene& scene);

  // Writes albedo H / pi into `out` (RGBA, alpha untouched) for every covered pixel of the
  // G-buffer; `irradiance` has one value per side. Returns the rays traced.
  std::size_t render(const Camera& camera, const HostImage& position, const HostImage& normal,
                     const HostImage& albedo, const std::vector<glm::dvec3>& irradiance,
                     PatchInterpolation interpolation, HostImage& out) const;

  // Per (side, corner) values, index 3 side + corner: Gouraud's vertex values.
  std::vector<glm::vec3> cornerValues(const std::vector<glm::dvec3>& perSide) const;
  std::size_t memoryBytes() const;

private:
  struct Share {
    std::uint32_t side;
    float weight;
  };
  const PatchMesh& mesh_;
  const PatchRayScene& scene_;
  std::vector<std::uint32_t> shareStart_;  // per (side, corner), into shares_; one more at the end
  std::vector<Share> shares_;
};

}  // namespace lpvlab
