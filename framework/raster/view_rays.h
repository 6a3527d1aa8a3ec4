#pragma once
// The rays a rasteriser's view samples: one through each texel centre of a width x height image
// of the view clipFromWorld (a camera's perspective, a light's cube face, a directional light's
// orthographic box), between its near and far planes, which is where GL clips. The texel
// (x, y), y = 0 the bottom row as GL stores images, has its centre at normalised device
// coordinates ((x + 0.5) / width * 2 - 1, (y + 0.5) / height * 2 - 1); GL covers the texel with
// the surface whose depth there is nearest, which is the ray's nearest hit.
//
// The near and far points of a texel are affine in (x, y) in homogeneous coordinates: their
// coefficients come from the matrix inverted in double precision (a near/far ratio of 1e4 loses
// no digit a float keeps), and each texel's ray is then a few float operations, as GL's own
// interpolation is float.

#include <glm/glm.hpp>

namespace lpvlab {

struct ViewRay {
  glm::vec3 origin;     // on the near plane
  glm::vec3 direction;  // unit, towards the far plane
  float length;         // from the near plane to the far plane along the ray
};

class ViewRays {
public:
  // Throws an Error when the matrix is not invertible or not finite, or the image is empty.
  ViewRays(const glm::mat4& clipFromWorld, int width, int height);

  // The ray through texel (x, y)'s centre.
  ViewRay ray(int x, int y) const { return rayAt(float(x) + 0.5f, float(y) + 0.5f); }
  // The ray through image position (px, py) in texels, (0, 0) the bottom-left corner: texel
  // centres and, for tests, any point within a texel.
  ViewRay rayAt(float px, float py) const {
    const glm::vec4 nearH = near_[0] + px * near_[1] + py * near_[2];
    const glm::vec4 farH = far_[0] + px * far_[1] + py * far_[2];
    const glm::vec3 nearPoint = glm::vec3(nearH) / nearH.w;
    const glm::vec3 span = glm::vec3(farH) / farH.w - nearPoint;
    const float length = glm::length(span);
    return {nearPoint, span / length, length};
  }
  // GL's window depth of a point (depth range 0..1, the default): what a depth buffer holds.
  float windowDepth(const glm::vec3& point) const {
    const float z = glm::dot(depthRow_, glm::vec4(point, 1.0f));
    const float w = glm::dot(wRow_, glm::vec4(point, 1.0f));
    return 0.5f * (z / w) + 0.5f;
  }
  int width() const { return width_; }
  int height() const { return height_; }

private:
  glm::vec4 near_[3], far_[3];  // homogeneous near/far point = [0] + px [1] + py [2]
  glm::vec4 depthRow_, wRow_;   // clip z and w as rows of clipFromWorld
  int width_, height_;
};

}  // namespace lpvlab
