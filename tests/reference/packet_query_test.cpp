// EmbreeScene's packet queries on every instruction set and query width, against one ray at a
// time through Embree's own single-ray query: the hits of active lanes agree bit for bit, and
// inactive lanes are never traced nor changed. Sparse packets are the case that aborted inside
// Embree on AVX2 machines, when inactive lanes held uninitialised rays that Embree's narrower
// kernels, splitting a 16-wide packet, checked.

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "framework/reference/embree_scene.h"
#include "framework/reference/random.h"
#include "framework/scene/scene_loader.h"
#include "instruction_sets.h"

namespace lpvlab {
namespace {

class PacketQuery : public testing::PerInstructionSet {
protected:
  Scene box = makeCornellBox();
  std::vector<SurfaceMaterial> materials = prepareMaterials(box);

  // A ray from inside the box in a direction drawn from `random`, turned away from the open
  // front (where the camera looks in), so it always hits a wall.
  void drawRay(SampleRandom& random, glm::vec3& origin, glm::vec3& direction) const {
    const Bounds bounds = box.bounds();
    origin = bounds.min + bounds.extent() * glm::vec3(0.25f + 0.5f * random.uniform(),
                                                      0.25f + 0.5f * random.uniform(),
                                                      0.25f + 0.5f * random.uniform());
    direction = glm::normalize(glm::vec3(random.uniform(), random.uniform(), random.uniform()) - 0.5f);
    const glm::vec3 inwards = box.cameras.front().forward;
    if (glm::dot(direction, inwards) < 0.1f)
      direction = glm::normalize(direction + (0.2f - 2.0f * glm::dot(direction, inwards)) * inwards);
  }
};

// Active-lane patterns: all, none, one at each end, every third, and one half.
std::vector<std::vector<bool>> activePatterns() {
  std::vector<std::vector<bool>> patterns(6, std::vector<bool>(kPacketWidth, false));
  for (int lane = 0; lane < kPacketWidth; ++lane) {
    patterns[0][lane] = true;
    patterns[3][lane] = lane % 3 == 1;
    patterns[4][lane] = lane >= kPacketWidth / 2;
  }
  patterns[2][0] = true;
  patterns[5][kPacketWidth - 1] = true;
  return patterns;
}

TEST_P(PacketQuery, ActiveLanesMatchSingleRaysAndInactiveLanesStayEmpty) {
  EmbreeScene single(box, materials, {isa(), 1});
  int hitsChecked = 0;
  for (int width : {0, 1, 4, 8, 16}) {
    EmbreeScene scene(box, materials, {isa(), width});
    SampleRandom random(7, std::uint64_t(width), 0);
    for (const std::vector<bool>& active : activePatterns()) {
      RayPacket packet;
      ShadowPacket occlusion;
      glm::vec3 origins[kPacketWidth], directions[kPacketWidth];
      for (int lane = 0; lane < kPacketWidth; ++lane) {
        if (!active[lane]) continue;
        drawRay(random, origins[lane], directions[lane]);
        packet.set(lane, origins[lane], directions[lane], 0.0f, INFINITY);
        // Shadow rays stopping halfway to the wall: half of them (by lane) reach it.
        occlusion.set(lane, origins[lane], directions[lane], 0.0f, 1e-3f);
      }
      scene.intersect(packet, false);
      scene.occluded(occlusion);
      for (int lane = 0; lane < kPacketWidth; ++lane) {
        if (!active[lane]) {
          EXPECT_FALSE(packet.hit(lane)) << "width " << width << ", inactive lane " << lane;
          EXPECT_EQ(packet.query.ray.tfar[lane], kInactiveTFar) << "width " << width;
          EXPECT_EQ(occlusion.query.tfar[lane], kInactiveTFar) << "width " << width;
          continue;
        }
        RayPacket one;
        one.set(0, origins[lane], directions[lane], 0.0f, INFINITY);
        single.intersect(one, false);
        ASSERT_TRUE(packet.hit(lane) && one.hit(0)) << "width " << width << ", lane " << lane;
        const RayHit a = packet.hitAt(lane), b = one.hitAt(0);
        EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0)
            << "width " << width << ", lane " << lane << ": t " << a.distance << " vs " << b.distance;
        // A 1 mm shadow ray from inside the box reaches no wall.
        EXPECT_FALSE(occlusion.occluded(lane)) << "width " << width << ", lane " << lane;
        ++hitsChecked;
      }
    }
  }
  EXPECT_GT(hitsChecked, 5 * 16);
}

TEST_P(PacketQuery, ShadowRaysToTheWallsAreBlockedInEveryLane) {
  for (int width : {0, 1, 4, 8, 16}) {
    EmbreeScene scene(box, materials, {isa(), width});
    SampleRandom random(11, std::uint64_t(width), 0);
    ShadowPacket occlusion;
    for (int lane = 0; lane < kPacketWidth; lane += 2) {  // every other lane: sparse
      glm::vec3 origin, direction;
      drawRay(random, origin, direction);
      occlusion.set(lane, origin, direction, 0.0f, INFINITY);
    }
    scene.occluded(occlusion);
    for (int lane = 0; lane < kPacketWidth; ++lane)
      if (lane % 2 == 0)
        EXPECT_TRUE(occlusion.occluded(lane)) << "width " << width << ", lane " << lane;
      else  // untouched: a hit would have set -inf
        EXPECT_EQ(occlusion.query.tfar[lane], kInactiveTFar) << "width " << width << ", lane " << lane;
  }
}

TEST_P(PacketQuery, TheDeviceReportsWhatItRuns) {
  const EmbreeScene native(box, materials, {isa(), 0});
  EXPECT_EQ(native.isa(), isa());
  // The widest width each instruction set traces natively.
  const int expected = isa() == "avx512" ? 16 : isa() == "sse4.2" ? 4 : 8;
  EXPECT_EQ(native.packetWidth(), expected);
  EXPECT_EQ(EmbreeScene(box, materials, {isa(), 4}).packetWidth(), 4);
}

LPVLAB_PER_INSTRUCTION_SET(PacketQuery);

}  // namespace
}  // namespace lpvlab
