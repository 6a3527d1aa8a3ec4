// makeTetrahedralOcclusion's body (tetrahedral_cpu.h), included by each translation unit that
// instantiates it after the shared GLSL of its precision (framework/math/shared.h:
// tetrahedral_lattice.glsl and a `GvLookup` struct over the GV's values): tetrahedral_cpu.cpp in
// double precision for the float and double kernels, tetrahedral_cpu_dual.cpp on dual numbers
// for the derivatives with respect to what the GV depends on. One text for both.
// Not a header of its own: no include guard, no declarations for other files.

namespace {

// Calls f(code, cube) for every lattice cell that exists (both its cubes inside the grid).
template <class F>
void forEachCell(const glm::ivec3& res, F&& f) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code)
    for (int z = 0; z < res.z; ++z)
      for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
          if (shared::tetInside(glm::ivec4(x, y, z, code), res)) f(code, glm::ivec3(x, y, z));
}

}  // namespace

template <class Real, class GvValue>
TetrahedralOcclusion<Real> makeTetrahedralOcclusion(const TetrahedralLattice<Real>& lattice,
                                                    const GvValue* gvBlocking) {
  TetrahedralOcclusion<Real> o;
  const glm::ivec3 res = lattice.resolution;
  o.resolution = res;
  o.transmittance.assign(std::size_t(shared::TET_PER_CUBE) * 12 * lattice.plane, Real(1));
  const shared::GvLookup blocking{gvBlocking};
  // A lattice cell lies within its two cubes' centres' span along its axis and within its cube
  // across it, so every crossing on its faces interpolates GV cells within [cube, cube + 2]: where
  // all 27 are empty, every face keeps T = 1 (most of a scene's GV is empty space).
  const glm::ivec3 gvRes = res + 1;
  const std::size_t gvCells = std::size_t(shared::cellCount(gvRes));
  std::vector<char> blocks(std::size_t(shared::cellCount(res)), 0);
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        char any = 0;
        for (int dz = 0; dz <= 2 && !any; ++dz)
          for (int dy = 0; dy <= 2 && !any; ++dy)
            for (int dx = 0; dx <= 2 && !any; ++dx) {
              const glm::ivec3 c(x + dx, y + dy, z + dz);
              if (!shared::cellInside(c, gvRes)) continue;
              const std::size_t i = std::size_t(shared::cellIndex(c, gvRes));
              for (std::size_t k = 0; k < 4; ++k) any |= !dual_number::isExactlyZero(gvBlocking[k * gvCells + i]);
            }
        blocks[std::size_t(shared::cellIndex(glm::ivec3(x, y, z), res))] = any;
      }
  // Per code and z-slice in parallel: each writes its own cells.
  tbb::parallel_for(tbb::blocked_range<int>(0, shared::TET_PER_CUBE * res.z), [&](const tbb::blocked_range<int>&
                                                                        r) {
    shared::GvLookup lookup = blocking;  // (its GLSL functions are not const members)
    for (int task = r.begin(); task < r.end(); ++task) {
      const int code = task / res.z, z = task % res.z;
      for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
          const glm::ivec4 tet(x, y, z, code);
          if (!shared::tetInside(tet, res) ||
              !blocks[std::size_t(shared::cellIndex(glm::ivec3(x, y, z), res))])
            continue;
          // The cell's index in a plane (at() without the channel, coefficient and code).
          const std::size_t cell = lattice.at(0, 0, 0, glm::ivec3(x, y, z));
          for (int j = 0; j < shared::TET_FACES; ++j)
            for (int k = 0; k < shared::TET_FACES; ++k) {
              if (k == j) continue;
              const shared::real t = shared::gvTransmittance(
                  lookup.gvBlockingAt(shared::tetFarFaceCrossing(tet, j, k), res + 1),
                  shared::tetFarFaceDirection(code, j, k));
              o.transmittance[std::size_t(code * 12 + tetrahedralFaceSlot(j, k)) * lattice.plane +
                              cell] = Real(t);
            }
        }
    }
  });
  return o;
}

