#pragma once
// Where each pixel's surface point of the current frame lies in the previous frame's image: the
// Reprojection the temporal metrics use (framework/metrics/temporal.h), built from the two
// frames' depth and normal AOVs and cameras through CameraRays, the G-buffer's own camera model.
//
// Current pixel (x, y) with view depth d > 0 sees the point p = surfacePoint(x + 0.5, y + 0.5, d)
// of the current camera. The previous camera projects p to image position (u, v), and the up to
// four pixel centres around it get bilinear weights. Each of them must see the same surface as
// p, else the pixel gets no taps (the point was hidden or off-screen in the previous frame):
//   - covered there (depth > 0) and inside the image;
//   - its point q within the tolerance of p's tangent plane: |n_p . (q - p)| <= planeTolerance d
//     (a relative tolerance, as depth precision and surface detail scale with distance);
//   - its normal within the angle of p's: |n_p . n_q| >= minNormalCosine (normals face the
//     camera that saw them, so their sign is not compared).
// A position within 1/1000 pixel of a pixel centre in x (or y) takes that column (or row) alone,
// so a camera that did not move maps every pixel onto itself exactly, not through the float
// rounding of a projection and its inverse.

#include "framework/io/image.h"
#include "framework/metrics/temporal.h"
#include "framework/scene/scene.h"

namespace lpvlab {

struct ReprojectionTolerances {
  float planeTolerance = 0.01f;  // of the view depth
  float minNormalCosine = 0.9f;  // about 25 degrees
};

struct FrameGeometry {
  const Camera& camera;
  const Image& depth;   // 1 channel, view depth in metres, 0 = no surface
  const Image& normal;  // RGB, unit world normals
};

// Throws an Error for AOVs of other sizes or channel counts, non-finite depths or normals, or a
// camera CameraRays refuses.
Reprojection reprojectThroughDepth(const FrameGeometry& now, const FrameGeometry& before,
                                   const ReprojectionTolerances& tolerances = {});

}  // namespace lpvlab
