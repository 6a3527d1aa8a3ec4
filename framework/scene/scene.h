#pragma once
// The scene as every renderer in lpvlab sees it: the LPV pipeline (GL) and the reference path
// tracer (Embree) read this one description, so they agree on geometry, materials, lights and
// cameras by construction.
//
// Conventions: metres; right-handed, +y up; radiometric units. All geometry is in world space:
// node transforms are applied and instanced meshes are flattened at load time.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "framework/math/bounds.h"

namespace lpvlab {

// A decoded image (the GL texture made from it is a gl::Texture).
struct TextureImage {
  std::string path;               // where it was read from (for messages; the scene hash uses the pixels)
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba8;  // row-major, top row first, sRGB-encoded colour, linear alpha
};

enum class AlphaMode { Opaque, Mask };

struct Material {
  std::string name;
  glm::vec3 baseColor{0.8f};       // linear Lambertian reflectance (albedo), each channel in [0,1]
  int baseColorTexture = -1;       // index into Scene::textures, multiplied with baseColor; -1: none
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;        // Mask: texels with alpha below this are cut out
  glm::vec3 emission{0.0f};        // emitted radiance, W/(m^2 sr) (OBJ Ke, glTF emissiveFactor)
  // The glossy lobe of the reference's [reference] brdf = "phong" (framework/reference/
  // phong_brdf.h): a dielectric's specular reflectance, the Phong exponent m, and how metallic the
  // surface is (glTF's metallicFactor: the lobe's reflectance moves towards the albedo and the
  // diffuse part fades). From OBJ's Ks and Ns, or glTF's metallic-roughness (specular 0.04, m from
  // roughnessFactor: assimp_materials.cpp). The Lambertian reference, the LPV pipeline and the
  // many-light methods ignore all three.
  glm::vec3 specular{0.0f};
  float shininess = 0.0f;
  float metallic = 0.0f;
  bool emits() const { return glm::any(glm::greaterThan(emission, glm::vec3(0.0f))); }
  // Translucency, read only by the subsurface-scattering LPV (thesis 5.4; rendering "subsurface";
  // set per experiment with [[materials]]): the fraction of the flux arriving at the surface that
  // enters the object (0: opaque; baseColor + transmittance <= 1 per channel), and the extinction
  // coefficient sigma of its interior, 1/m (light travelling a distance d keeps exp(-sigma d)).
  // The reference path tracer ignores both: it renders translucent materials as opaque.
  glm::vec3 transmittance{0.0f};
  float extinction = 0.0f;
  bool translucent() const { return glm::any(glm::greaterThan(transmittance, glm::vec3(0.0f))); }
  // Drawn into the reflective shadow maps, whose texels are the VPLs of injection and of the
  // many-light methods: false for the copies of a particle system with inject = false
  // (docs/particles.md). Not in the scene hash: the reference does not read it.
  bool injects = true;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // world space, metres
  std::vector<glm::vec3> normals;    // world space, unit length, one per position
  std::vector<glm::vec2> uvs;        // one per position (zero when the file has none); (0,0) is the
                                     // top-left corner of a texture (glTF's convention)
  // Vertex colours: empty, or one per position, linear RGB in [0, 1] that multiplies the
  // material's albedo (base colour x texture) at the interpolated point; not the emission. Every
  // renderer reads them (raster passes, path tracer, radiosity's patches): what gives each of a
  // particle system's copies its colour over the life (framework/particles).
  std::vector<glm::vec3> colors;
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from the normal side
  int material = 0;                  // index into Scene::materials
  // false: the LPV pipeline's raster passes leave the mesh out, because something else draws it
  // there (a particle system's copies of its model when light-field billboards show them,
  // framework/particles); the path tracer and every other renderer see it as any mesh.
  bool rasterised = true;
};

enum class LightType { Point, Spot, Directional };
// "point", "spot", "directional": the names experiment files use.
const char* lightTypeName(LightType type);

struct Light {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};        // Point, Spot: world space, metres
  glm::vec3 direction{0, -1, 0};   // Spot, Directional: unit vector the light travels along
  glm::vec3 color{1.0f};           // linear RGB, multiplied with intensity
  // Point, Spot: radiant intensity, W/sr. Directional: irradiance on a surface facing the
  // light, W/m^2. (glTF's KHR_lights_punctual candela and lux are read as these.)
  float intensity = 1.0f;
  float innerConeAngle = 0.0f;     // Spot: half-angles in radians, glTF smooth falloff between
  float outerConeAngle = 0.7853982f;
};

struct Camera {
  std::string name;
  glm::vec3 position{0.0f};
  glm::vec3 forward{0, 0, -1};     // unit view direction
  glm::vec3 up{0, 1, 0};           // unit, orthogonal to forward
  float verticalFov = 0.6861f;     // radians, full angle
  float nearPlane = 0.01f;         // metres
  float farPlane = 100.0f;
};

// Points `camera` from its position at `target`, its up vector the part of `up` orthogonal to
// the view. Returns false, leaving the camera as it was, when `target` is (within 1e-6 m) the
// camera's position or `up` is parallel to the view.
enum class CameraOrientation { Oriented, TargetAtPosition, UpAlongView };
CameraOrientation orientCamera(Camera& camera, const glm::vec3& target, const glm::vec3& up);

// A node animation of the scene file (glTF animations, read through Assimp;
// framework/scene/assimp_animations.cpp): the rigid motion of the meshes the node and its
// descendants place, in world space, relative to the file's rest pose. At time t a point p of
// them as loaded goes to pivot + R(t) (p - pivot) + T(t), with T and R interpolated between
// their keys as `interpolation` says ("linear": linear and slerp; "step"); before the first key
// and after the last the key is held. An experiment plays it with [animation] scene_animation.
struct NodeAnimation {
  std::string animation;               // the file's animation (clip) name
  std::string node;                    // the animated node
  std::vector<int> meshes;             // indices into Scene::meshes
  glm::dvec3 pivot{0.0};               // the node's origin at rest, world space
  std::vector<double> translationTimes;  // seconds, increasing; empty: no translation
  std::vector<glm::dvec3> translations;  // T, metres
  std::string translationInterpolation = "linear";
  std::vector<double> rotationTimes;   // seconds, increasing; empty: no rotation
  std::vector<glm::dquat> rotations;   // R, unit
  std::string rotationInterpolation = "linear";
};

struct Scene {
  std::string source;              // file path, or "builtin:cornell_box"
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<TextureImage> textures;
  std::vector<Light> lights;
  std::vector<Camera> cameras;
  std::vector<NodeAnimation> nodeAnimations;  // the file's, none for the built-in scenes

  std::size_t triangleCount() const;
  Bounds bounds() const;           // of all triangles
};

}  // namespace lpvlab
