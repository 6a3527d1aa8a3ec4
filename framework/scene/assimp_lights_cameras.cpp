// What Assimp 5.2's glTF importer stores (checked on 5.2.5; glTF is the only format lpvlab
// reads that has lights and cameras):
// - KHR_lights_punctual: position (0,0,0) and direction (0,0,-1) in the node's space; the
//   colour already multiplied by the intensity; spot cone angles as glTF's half-angles in
//   radians, unchanged. A light's optional range goes into node metadata and is not read here:
//   lpvlab's lights fall off with the inverse square everywhere.
// - Perspective cameras: mLookAt (0,0,-1) and mUp (0,1,0) in the node's space;
//   mHorizontalFOV = yfov * aspectRatio (or yfov when there is no aspect ratio), which is
//   neither the horizontal FOV nor a half-angle; mPosition = the node's translation, which the
//   node transform applies a second time.

#include <algorithm>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"

namespace lpvlab {
namespace {

glm::vec3 toVec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

}  // namespace

Light convertLight(const aiLight& in, const glm::mat4& toWorld, const std::string& path) {
  Light out;
  out.name = in.mName.C_Str();
  switch (in.mType) {
    case aiLightSource_POINT: out.type = LightType::Point; break;
    case aiLightSource_SPOT: out.type = LightType::Spot; break;
    case aiLightSource_DIRECTIONAL: out.type = LightType::Directional; break;
    case aiLightSource_AREA:
      throwAt(path, "light '" + out.name + "' is an area light; lpvlab supports point, spot and "
                    "directional lights (use an emissive material for area lights)");
    default:
      throwAt(path, "light '" + out.name + "' has a type lpvlab can't use (Assimp type " +
                        std::to_string(static_cast<int>(in.mType)) +
                        "); lpvlab supports point, spot and directional lights");
  }
  out.position = glm::vec3(toWorld * glm::vec4(toVec3(in.mPosition), 1.0f));
  if (out.type != LightType::Point)
    out.direction = glm::normalize(glm::mat3(toWorld) * toVec3(in.mDirection));

  // Assimp keeps only colour * intensity. Splitting it as intensity = its largest channel gives
  // back the file's colour whenever that colour's largest channel is 1 (white, and most files),
  // and colour * intensity equals the file's product in every case.
  const glm::vec3 radiant{in.mColorDiffuse.r, in.mColorDiffuse.g, in.mColorDiffuse.b};
  out.intensity = std::max({radiant.r, radiant.g, radiant.b});
  out.color = out.intensity > 0.0f ? radiant / out.intensity : glm::vec3(1.0f);

  if (out.type == LightType::Spot) {
    out.innerConeAngle = in.mAngleInnerCone;
    out.outerConeAngle = in.mAngleOuterCone;
  }
  return out;
}

Camera convertCamera(const aiCamera& in, const glm::mat4& toWorld, const std::string& path) {
  Camera out;
  out.name = in.mName.C_Str();
  if (in.mHorizontalFOV == 0.0f && in.mOrthographicWidth > 0.0f)
    throwAt(path, "camera '" + out.name + "' is orthographic; lpvlab supports perspective cameras");

  // A glTF camera sits at its node's origin (mPosition would count the translation twice).
  // The node may scale: directions are normalised, and up is made orthogonal to forward.
  const glm::mat3 linear(toWorld);
  out.position = glm::vec3(toWorld[3]);
  out.forward = glm::normalize(linear * toVec3(in.mLookAt));
  const glm::vec3 up = linear * toVec3(in.mUp);
  out.up = glm::normalize(up - glm::dot(up, out.forward) * out.forward);

  out.verticalFov = in.mAspect > 0.0f ? in.mHorizontalFOV / in.mAspect : in.mHorizontalFOV;
  out.nearPlane = in.mClipPlaneNear;
  out.farPlane = in.mClipPlaneFar;
  return out;
}

}  // namespace lpvlab
