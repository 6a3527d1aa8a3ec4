#pragma once
// Solid angles of cell faces, derived from the geometry rather than pasted: the constants that
// public LPV code copies (0.4006696846, 0.4234413544 with its typo) are computed here in double
// precision and tested against closed forms and numerical integration.

#include <glm/glm.hpp>

namespace lpvlab {

// Solid angle (sr) of the triangle (a, b, c) seen from the origin (Van Oosterom and Strackee
// 1983): tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|).
double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Solid angle of the planar convex quadrilateral a-b-c-d seen from the origin.
double quadSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      const glm::dvec3& d);

// The two face solid angles of standard (cubic-cell) propagation. A source cell at the origin
// with unit edge sends light into a neighbour centred at (0, 0, 1); of the neighbour's six faces,
// the five not shared with the source receive it:
//   farFace:  the face opposite the shared one, z = 1.5: 4 asin(1/10) = 0.40066968...
//   sideFace: each of the four faces x = +-0.5 / y = +-0.5 with z in [0.5, 1.5]:
//             (2 pi / 3 - farFace) / 4 = 0.42343135...
// Together they fill the solid angle of the shared face, 2 pi / 3, and the 6 neighbours' 30
// faces tile the whole sphere, 4 pi.
struct CubeFaceSolidAngles {
  double farFace;
  double sideFace;
};
CubeFaceSolidAngles cubeFaceSolidAngles();

}  // namespace lpvlab
