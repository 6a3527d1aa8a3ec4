#pragma once
// Directed propagation (directed.cpp) on the CPU: its two kernels' work, from the same shared
// GLSL (directed_faces.glsl), split as the CPU does it best.
//
// directed_gather.comp is standard gathering whose cells with a normal re-emit what their faces
// pass as a cosine lobe about that normal: with Phi_n the fluxes through the cell's faces of
// normal n (summed, as the standard CPU kernel sums them), the cell's coefficients are
//     (sum_n Phi_n * directedReprojection(n, normal, G(normal))) * cosLobe_k(normal)
// in place of sum_n Phi_n lobe_n,k / pi. So the CPU runs the standard kernel (standard_cpu.h),
// which does the faces, the GV and the sums, with ReprojectedCells finishing each cell that has a
// normal: its six weights and its lobe.
//
// Those change only when a cell's normal does, and a cell's normal, once it has one, never
// changes (dilation keeps a cell's own normal, directed_faces.glsl's directedDilated). So the
// dilation of directed_dilate.comp, run iteration by iteration here on the host, only finds the
// iteration in which each cell first has a normal (`since`; 0 for injected cells and, with
// dilation, for their neighbours, which the dilation before iteration 0 reaches), and each cell's
// gain G(n) (60 lobe evaluations) is found once per frame, not once per iteration as on GL. The
// strategy keeps the result while the injected normals stay the same bit for bit.

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "variants/propagation/standard_cpu.h"

namespace lpvlab {

// The cells of a grid of `resolution` reprojecting in `iterations` steps of directed
// propagation from `injectedNormals` (vec4 per cell, as injection leaves them: flux-weighted
// normal sum and flux), with the normals dilated before every iteration or not (then only the
// injected cells reproject). `table`: the standard transfer's (its solid angles and order).
template <class Real>
ReprojectedCells<Real> makeDirectedCells(const StandardFaceTable<Real>& table,
                                         const glm::ivec3& resolution,
                                         const std::vector<float>& injectedNormals, int iterations,
                                         bool dilation, double farSolidAngle,
                                         double sideSolidAngle);

// With release (directed_faces.glsl): the iterations in which each cell keeps its attached light,
// from the same dilation: a cell keeps it from the iteration it has a normal until the first in
// which a neighbour has a normal of another region (its unit normal further than the region angle,
// `cosRegionAngle` its cosine, from the cell's).
ReleasedCells makeReleasedCells(const glm::ivec3& resolution,
                                const std::vector<float>& injectedNormals, int iterations,
                                bool dilation, double cosRegionAngle);

// Both from one dilation, as the strategy needs them (with release: `cosRegionAngle` given;
// without, `released` stays empty).
template <class Real>
struct DirectedCells {
  ReprojectedCells<Real> reprojected;
  ReleasedCells released;
};
template <class Real>
DirectedCells<Real> makeDirectedAndReleasedCells(const StandardFaceTable<Real>& table,
                                                 const glm::ivec3& resolution,
                                                 const std::vector<float>& injectedNormals,
                                                 int iterations, bool dilation,
                                                 double farSolidAngle, double sideSolidAngle,
                                                 std::optional<double> cosRegionAngle);

}  // namespace lpvlab
