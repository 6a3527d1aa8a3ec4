#pragma once
// The colour spaces of FLIP (Andersson et al. 2020, section 3 and the reference code): linear
// sRGB, CIE XYZ, the linear opponent space YCxCz (Wandell and Zhang's) where the contrast
// sensitivity filters act, and Hunt-adjusted CIELAB where the colour difference is measured.
// All relative to the D65 white of sRGB, the XYZ of linear RGB (1, 1, 1).

#include <glm/glm.hpp>

namespace lpvlab::flip {

// Linear sRGB (D65) <-> XYZ. The forward matrix is FLIP's, in exact fractions; the inverse is
// computed from it (FLIP's code writes it to 9 digits).
glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb);
glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz);

// YCxCz: Y = 116 y - 16, Cx = 500 (x - y), Cz = 200 (y - z), with (x, y, z) = XYZ / white.
// Like L*a*b* without the cube root, so it stays linear and filtering in it is meaningful.
glm::dvec3 xyzToYCxCz(const glm::dvec3& xyz);
glm::dvec3 yCxCzToXyz(const glm::dvec3& ycxcz);

// CIE 1976 L*a*b*: f(t) = t^(1/3) above (6/29)^3, else t / (3 (6/29)^2) + 4/29.
glm::dvec3 xyzToLab(const glm::dvec3& xyz);

// Hunt effect (colourfulness grows with luminance): a* and b* scaled by 0.01 L*.
glm::dvec3 huntAdjust(const glm::dvec3& lab);

// HyAB distance (Abasi et al. 2020): |dL| + sqrt(da^2 + db^2), city block in lightness and
// Euclidean in chroma, which suits large differences better than Delta E.
double hyab(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace lpvlab::flip
