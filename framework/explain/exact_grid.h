#pragma once
// lpvlab explain's propagation oracle (docs/explain.md#the-oracles): the light grid LPV would hold
// if propagation were exact. Each cell's entry is the radiance arriving at its centre c from the
// VPLs, projected on the grid's SH basis and stored as the grid stores light (intensity, W/sr:
// radiance times the cell's cross-section, as shaders/rendering/trilinear_diffuse.glsl reads it):
//
//   c_k = sum_v  I_v(w_v) * s^2 / max(d_v^2, s^2) * Y_k(w_v) * V(v, c)
//
// with w_v the unit direction from VPL v to c (the light at c travels along it), d_v their
// distance, s the cell size, I_v(w) = phi_v / pi * max(0, n_v . w) (vpl.h) and V the visibility
// from the cell: the fraction of its 8 sub-cell centres (c +- s/4 on each axis) that a shadow ray
// from just above the VPL reaches (1 without visibility). A single point would be all or nothing,
// and a coarse grid puts many centres inside walls and columns, which would make the grid
// darker than the light around them; the fraction is what the GV's partial blocking models. A point light seen from
// distance d is radiance I / d^2 within a delta of solid angle, whose projection on Y_k is
// I / d^2 * Y_k(w). Closer than a cell, the VPL's light is spread over the cell's cross-section as
// LPV's injection spreads it (I / s^2), which keeps a VPL near a centre from giving an unbounded
// value. The VPLs sit where the RSM saw them: LPV's injection shift is part of what the oracle
// does not do.
//
// Limits: a cell wholly inside a wall sees no VPL (with visibility); the light's direction is
// taken from the centre; the grid's SH order truncates the exact angular distribution as it
// truncates LPV's.

#include <functional>
#include <span>
#include <vector>

#include "framework/many_lights/vpl.h"
#include "framework/math/grid_geometry.h"

namespace lpvlab {

class EmbreeScene;

// The grid (shaders/common/grid.glsl's layout: 3 channels x `coefficients` x cells, 4, 9 or 16
// coefficients) from `vpls`; `visibility` traces the shadow rays (null: no visibility).
// `progress`, if given, is called with the fraction of cells done. Throws an Error for a
// coefficient count the basis lacks.
std::vector<float> exactLightGrid(std::span<const Vpl> vpls, const GridGeometry& grid,
                                  int coefficients, const EmbreeScene* visibility,
                                  const std::function<void(double)>& progress = {});

}  // namespace lpvlab
