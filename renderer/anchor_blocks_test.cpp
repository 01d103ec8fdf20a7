#include "renderer/anchor_blocks.h"

#include <gtest/gtest.h>

#include "renderer/adaptive_sampling.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

RenderSettings smallImage() {
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  return settings;
}

TEST(AnchorBlocks, AnObjectReachesTheBlocksItsBoxProjectsOnto) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere, {scale(0.1)}));
  RenderScene compiled(s);
  RenderSettings settings = smallImage();
  PinholeCamera camera(compiled.camera(), settings);
  AnchorBlocks blocks(compiled, camera, settings.width, settings.height);
  std::uint32_t sphere = compiled.boundedObjects()[0];
  // The image's centre (32, 24): the sphere, a few pixels across, alone.
  EXPECT_TRUE(blocks.onlyShows(33, 24, sphere));
  EXPECT_FALSE(blocks.onlyShows(33, 24, RaySource::kNone));
  EXPECT_FALSE(blocks.onlyShows(32, 25, sphere + 1));
  // Far from it: nothing.
  EXPECT_TRUE(blocks.onlyShows(3, 3, RaySource::kNone));
  EXPECT_TRUE(blocks.onlyShows(63, 47, RaySource::kNone));
}

// Blocks of 4 x 4 pixels (the coarse anchors'): a corner reads the block
// it lies in, which holds the 2 x 2 blocks inside it, so an object that
// reaches one of those reaches it too.
TEST(AnchorBlocks, CoarseBlocksSpanFourPixels) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere, {scale(0.1)}));
  RenderScene compiled(s);
  RenderSettings settings = smallImage();
  PinholeCamera camera(compiled.camera(), settings);
  AnchorBlocks fine(compiled, camera, settings.width, settings.height);
  AnchorBlocks coarse(compiled, camera, settings.width, settings.height, 4);
  std::uint32_t sphere = compiled.boundedObjects()[0];
  EXPECT_TRUE(coarse.onlyShows(34, 24, sphere));
  EXPECT_FALSE(coarse.onlyShows(34, 24, RaySource::kNone));
  EXPECT_TRUE(coarse.onlyShows(6, 6, RaySource::kNone));
  // Every corner a span-2 block finds the sphere near, the 4 x 4 block
  // around it finds too.
  for (int y = 0; y <= settings.height; ++y) {
    for (int x = 0; x <= settings.width; ++x) {
      if (((x | y) & 1) == 0 || fine.onlyShows(x, y, RaySource::kNone)) continue;
      EXPECT_FALSE(coarse.onlyShows(x - (x & 1), y - (y & 1), RaySource::kNone)) << x << "," << y;
    }
  }
}

TEST(AnchorBlocks, ABoxAcrossTheEyePlaneReachesEveryBlock) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Cube, {scale(0.1), translate(0, 0, 0)}));
  s.objects.push_back(object(ObjectKind::Cube, {scale(1, 1, 10)}));
  RenderScene compiled(s);
  RenderSettings settings = smallImage();
  PinholeCamera camera(compiled.camera(), settings);
  AnchorBlocks blocks(compiled, camera, settings.width, settings.height);
  EXPECT_FALSE(blocks.onlyShows(3, 3, RaySource::kNone));
  EXPECT_FALSE(blocks.onlyShows(63, 46, RaySource::kNone));
  // Two objects at the centre: neither alone.
  for (std::uint32_t object : {0u, 1u}) EXPECT_FALSE(blocks.onlyShows(33, 24, object));
}

// A render's memory estimate counts the blocks: one for every 2 x 2 pixels,
// the odd row and column included, and one for every 4 x 4 (the coarse
// anchors').
TEST(AnchorBlocks, TheirBytesAreInTheAdaptiveSamplingEstimate) {
  EXPECT_EQ(AnchorBlocks::bytesFor(1920, 1080), std::uint64_t{960} * 540 * 8);
  EXPECT_EQ(AnchorBlocks::bytesFor(5, 3), std::uint64_t{3} * 2 * 8);
  EXPECT_EQ(AnchorBlocks::bytesFor(1920, 1080, 4), std::uint64_t{480} * 270 * 8);
  EXPECT_EQ(AnchorBlocks::bytesFor(5, 3, 4), std::uint64_t{2} * 1 * 8);
  // The estimate less a thread's share (what a second thread adds) and the
  // tiles' edge corners is the blocks'.
  std::uint64_t oneThread = adaptiveSamplingBytes(1920, 1080, 1, 32);
  std::uint64_t perThread = adaptiveSamplingBytes(1920, 1080, 2, 32) - oneThread;
  EXPECT_EQ(oneThread - perThread - TileEdgeCorners::bytesFor(1920, 1080, 32),
            AnchorBlocks::bytesFor(1920, 1080) + AnchorBlocks::bytesFor(1920, 1080, 4));
}

}  // namespace
}  // namespace render
