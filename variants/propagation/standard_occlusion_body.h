// makeStandardOcclusion's body (standard_cpu.h), included by each translation unit that
// instantiates it after the shared GLSL of its precision (framework/math/shared.h:
// standard_faces.glsl and a `GvLookup` struct over the GV's values): standard_cpu.cpp in double
// precision for the float and double kernels, standard_cpu_dual.cpp on dual numbers for the
// derivatives with respect to what the GV depends on (its blocking_scale). One text, so both
// find the same faces, crossings and transmittances.
// Not a header of its own: no include guard, no declarations for other files.

namespace {

// Per table entry (light from neighbour `direction` into the face with `normal`), the face index
// f of standard_faces.glsl for the flow -offset, or -1 for the shared face.
struct FaceGeometry {
  int face[6][6];
  shared::vec3 flow[6];  // -offset: the direction light flows
};

FaceGeometry faceGeometry(const glm::ivec3 (&offset)[6]) {
  FaceGeometry g{};
  for (int direction = 0; direction < 6; ++direction) {
    g.flow[direction] = -shared::vec3(offset[direction]);
    for (int normal = 0; normal < 6; ++normal) g.face[direction][normal] = -1;
    for (int f = 0; f < shared::STANDARD_FACES; ++f) {
      const shared::vec3 n = shared::standardFaceNormal(g.flow[direction], f);
      for (int normal = 0; normal < 6; ++normal)
        if (shared::vec3(offset[normal]) == n) g.face[direction][normal] = f;
    }
  }
  return g;
}

}  // namespace

template <class Real, class GvValue>
StandardOcclusion<Real> makeStandardOcclusion(const StandardFaceTable<Real>& table,
                                              const glm::ivec3& res, const GvValue* gvBlocking,
                                              std::type_identity_t<const GvValue*> gvAlbedo) {
  using shared::real;
  using shared::vec3;
  using shared::vec4;
  StandardOcclusion<Real> o;
  o.resolution = res;
  o.coefficients = table.coefficients;
  o.width = standardCpuRowWidth(res.x);
  const int rows = res.y * res.z, N = table.coefficients;
  constexpr int kFaces = StandardOcclusion<Real>::kFaces;
  o.transmittance.assign(std::size_t(kFaces) * rows * o.width, Real(1));
  const glm::ivec3 gvRes = res + 1;
  const std::size_t gvCells = std::size_t(gvRes.x) * gvRes.y * gvRes.z;
  shared::GvLookup blocking{gvBlocking};  // (its GLSL functions are not const members)
  // The albedo's (rho A, A) are interpolated as the blocking is (standard_transfer.glsl's
  // gvAlbedoFromCorners): the same lookup over a coefficient-major copy.
  std::vector<GvValue> albedoByComponent;
  if (gvAlbedo) {
    albedoByComponent.resize(4 * gvCells);
    for (std::size_t i = 0; i < gvCells; ++i)
      for (std::size_t c = 0; c < 4; ++c) albedoByComponent[c * gvCells + i] = gvAlbedo[4 * i + c];
  }
  shared::GvLookup albedo{albedoByComponent.data()};
  const FaceGeometry faces = faceGeometry(table.offset);
  // Whether GV cell c blocks anything (a cell whose eight corners are all empty lets every face
  // through whole, T = 1, and blocks nothing to bounce).
  auto empty = [&](const glm::ivec3& c) {
    const std::size_t i = std::size_t(shared::cellIndex(c, gvRes));
    for (std::size_t k = 0; k < 4; ++k)
      if (!dual_number::isExactlyZero(gvBlocking[k * gvCells + i])) return false;
    return true;
  };
  std::vector<std::vector<typename StandardOcclusion<Real>::Bounce>> bounces(gvAlbedo ? rows : 0);
  std::vector<std::vector<Real>> lobes(gvAlbedo ? rows : 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    for (int row = range.begin(); row < range.end(); ++row) {
      const int y = row % res.y, z = row / res.y;
      for (int x = 0; x < res.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        bool blocked = false;
        for (int corner = 0; corner < 8 && !blocked; ++corner)
          blocked = !empty(cell + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
        if (!blocked) continue;
        const vec3 centre = vec3(cell) + real(0.5);
        for (int direction = 0; direction < 6; ++direction)
          for (int normal = 0; normal < 6; ++normal) {
            const int f = faces.face[direction][normal];
            if (f < 0) continue;
            const vec3 flow = faces.flow[direction];
            const vec3 w = shared::standardFaceDirection(flow, f);
            // Light from the neighbour into this cell: the shared face is this cell's.
            const vec3 in =
                shared::standardFaceCrossing(centre + vec3(table.offset[direction]), flow, f);
            const real t = shared::gvTransmittance(blocking.gvBlockingAt(in, gvRes), w);
            o.transmittance[(std::size_t(standardFaceSlot(direction, normal)) * rows + row) * o.width + x] = Real(t);
            if (!gvAlbedo) continue;
            // This cell's own light leaving along `flow` through the same kind of face.
            const vec3 out = shared::standardFaceCrossing(centre, flow, f);
            const vec4 b = blocking.gvBlockingAt(out, gvRes);
            const real tOut = shared::gvTransmittance(b, w);
            if (!(tOut < real(1.0))) continue;
            const vec3 rho = shared::gvMeanAlbedo(albedo.gvBlockingAt(out, gvRes));
            if (rho == vec3(real(0.0))) continue;
            const vec3 n = shared::gvSurfaceNormal(b, w);
            typename StandardOcclusion<Real>::Bounce bounce{x, direction, normal, {}};
            for (int c = 0; c < 3; ++c) bounce.weight[c] = Real(rho[c] * (real(1.0) - tOut));
            bounces[std::size_t(row)].push_back(bounce);
            for (int k = 0; k < N; ++k)
              lobes[std::size_t(row)].push_back(Real(shared::shCosineLobeAt(k, n) / shared::PI));
          }
      }
    }
  });
  o.firstBounce.assign(std::size_t(rows) + 1, 0);
  for (int row = 0; row < rows && gvAlbedo; ++row) {
    o.firstBounce[std::size_t(row) + 1] = o.firstBounce[std::size_t(row)] + bounces[std::size_t(row)].size();
    o.bounces.insert(o.bounces.end(), bounces[std::size_t(row)].begin(), bounces[std::size_t(row)].end());
    o.bounceLobes.insert(o.bounceLobes.end(), lobes[std::size_t(row)].begin(), lobes[std::size_t(row)].end());
  }
  return o;
}
