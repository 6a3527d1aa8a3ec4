#pragma once
// How the ray-cast raster passes (ray_raster.h) trace a view: one ray per texel centre, 4 x 4
// texels of a tile to one 16-ray packet flagged coherent, rows of tiles shared out by oneTBB. The
// passes and the raster benchmark (tests/benchmarks/raster_rays_benchmark.cpp, which times the
// same rays without shading) both cast through it.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/raster/view_rays.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

constexpr int kRasterTile = 4;  // texels per side of a tile: kRasterTile^2 = one 16-ray packet
static_assert(kRasterTile * kRasterTile == kPacketWidth);

// Calls shade(x, y, ray, hit) for every texel of the view, hit null where the ray meets nothing
// between the near and far planes. Alpha masks cut where `alpha` says (null: at the texture's
// level 0); each ray's id is its texel's index, y * width + x, for the lookup to find its texel.
template <class Shade>
void castView(const EmbreeScene& scene, const ViewRays& rays, const AlphaLookup* alpha, Shade&& shade) {
  const int tilesX = (rays.width() + kRasterTile - 1) / kRasterTile;
  const int tilesY = (rays.height() + kRasterTile - 1) / kRasterTile;
  tbb::parallel_for(tbb::blocked_range<int>(0, tilesY), [&](const tbb::blocked_range<int>& tileRows) {
    RayPacket packet;
    ViewRay lanes[kPacketWidth];
    for (int tileY = tileRows.begin(); tileY < tileRows.end(); ++tileY)
      for (int tileX = 0; tileX < tilesX; ++tileX) {
        packet.clear();
        for (int lane = 0; lane < kPacketWidth; ++lane) {
          const int x = tileX * kRasterTile + lane % kRasterTile;
          const int y = tileY * kRasterTile + lane / kRasterTile;
          if (x >= rays.width() || y >= rays.height()) continue;
          lanes[lane] = rays.ray(x, y);
          packet.set(lane, lanes[lane].origin, lanes[lane].direction, 0.0f, lanes[lane].length,
                     unsigned(y) * unsigned(rays.width()) + unsigned(x));  // ViewAlpha reads it
        }
        scene.intersect(packet, /*coherent=*/true, alpha);
        for (int lane = 0; lane < kPacketWidth; ++lane) {
          if (!packet.active(lane)) continue;
          const int x = tileX * kRasterTile + lane % kRasterTile;
          const int y = tileY * kRasterTile + lane / kRasterTile;
          if (packet.hit(lane)) {
            const RayHit hit = packet.hitAt(lane);
            shade(x, y, lanes[lane], &hit);
          } else {
            shade(x, y, lanes[lane], static_cast<const RayHit*>(nullptr));
          }
        }
      }
  });
}

}  // namespace lpvlab
