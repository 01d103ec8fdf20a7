#include "renderer/anchor_blocks.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace render
