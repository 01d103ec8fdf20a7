// Regions and tiles of a render hold exactly the full render's pixels, for
// uniform and adaptive sampling alike (docs/RENDERING.md, "Regions and
// tiles").
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

// A mirror floor, a glass sphere in front of a diffuse cube, two lights:
// reflection, refraction and edges of every kind.
scene::Scene glassAndMirror() {
  scene::Scene s = sceneLookingAt({0, 2, 6}, {0, 0.5, 0});
  scene::Material mirror;
  mirror.colour = {0.6, 0.6, 0.65};
  mirror.reflectivity = 0.6;
  s.objects.push_back(object(ObjectKind::Plane, {}, mirror));
  scene::Material glass;
  glass.colour = {0.9, 0.95, 1.0};
  glass.transparency = 0.85;
  glass.ri = 1.5;
  glass.reflectivity = 0.1;
  s.objects.push_back(object(ObjectKind::Sphere, {translate(0, 1, 1)}, glass));
  scene::Material red;
  red.colour = {0.8, 0.2, 0.1};
  s.objects.push_back(object(ObjectKind::Cube, {scale(0.7), translate(0.8, 0.7, -1.5)}, red));
  s.lights.push_back(light({-4, 6, 5}, {0.7, 0.7, 0.7}));
  s.lights.push_back(light({5, 4, 2}, {0.4, 0.4, 0.45}));
  return s;
}

// Whether pixel (x, y) of the full image holds the same float bits as the
// region's pixel there, colour and coverage.
void expectSamePixels(const Image& full, const Image& part, const std::string& what) {
  ASSERT_EQ(part.fullWidth, full.width) << what;
  ASSERT_EQ(part.fullHeight, full.height) << what;
  ASSERT_EQ(part.rgb.size(), static_cast<std::size_t>(part.width) * part.height * 3) << what;
  ASSERT_EQ(part.coverage.empty(), full.coverage.empty()) << what;
  for (int y = 0; y < part.height; ++y) {
    for (int x = 0; x < part.width; ++x) {
      std::size_t in = static_cast<std::size_t>(y) * part.width + x;
      std::size_t at = static_cast<std::size_t>(part.originY + y) * full.width + part.originX + x;
      ASSERT_EQ(std::memcmp(&part.rgb[3 * in], &full.rgb[3 * at], 3 * sizeof(float)), 0)
          << what << " at " << part.originX + x << "," << part.originY + y;
      if (!part.coverage.empty()) {
        ASSERT_EQ(part.coverage[in], full.coverage[at]) << what;
      }
    }
  }
}

TEST(RenderRegion, TilesAreBandsOfWholeRowsThatCoverTheImage) {
  for (int count : {1, 2, 3, 4, 7, 36}) {
    int next = 0;
    for (int i = 0; i < count; ++i) {
      PixelRegion band = imageTile(48, 36, i, count);
      EXPECT_EQ(band.x0, 0);
      EXPECT_EQ(band.x1, 48);
      EXPECT_EQ(band.y0, next) << i << " of " << count;
      EXPECT_GE(band.height(), 36 / count);
      EXPECT_LE(band.height(), 36 / count + 1);
      next = band.y1;
    }
    EXPECT_EQ(next, 36) << count;
  }
  EXPECT_TRUE(imageTile(48, 36, 4, 4).empty());
  EXPECT_TRUE(imageTile(48, 36, -1, 4).empty());
  EXPECT_TRUE(imageTile(48, 3, 0, 4).empty());  // more bands than rows
}

TEST(RenderRegion, AFullRenderSaysSo) {
  RenderSettings settings;
  settings.width = 20;
  settings.height = 10;
  Image image = renderImage(RenderScene(defaultScene()), settings);
  EXPECT_EQ(image.originX, 0);
  EXPECT_EQ(image.originY, 0);
  EXPECT_EQ(image.fullWidth, 20);
  EXPECT_EQ(image.fullHeight, 10);
  settings.region = PixelRegion{15, 8, 30, 30};  // cut to the image
  Image cut = renderImage(RenderScene(defaultScene()), settings);
  EXPECT_EQ(cut.width, 5);
  EXPECT_EQ(cut.height, 2);
}

// What a region's render chooses by the image's samples (the BVH's kind)
// counts the whole image's, so that it chooses as the full render does; the
// samples it takes are its own.
TEST(RenderRegion, TheWholeImagesSamplesWhateverTheRegion) {
  RenderSettings settings;
  settings.width = 20;
  settings.height = 10;
  settings.samplesPerPixel = 4;
  EXPECT_EQ(fullImageSampleCount(settings), 800u);
  EXPECT_EQ(uniformSampleCount(settings), 800u);
  settings.region = PixelRegion{15, 8, 30, 30};
  EXPECT_EQ(fullImageSampleCount(settings), 800u);
  EXPECT_EQ(uniformSampleCount(settings), 40u);
  settings.samplesPerPixel = 0;
  EXPECT_EQ(fullImageSampleCount(settings), 200u);
}

TEST(RenderRegion, EveryRegionAndTileHoldsTheFullRendersPixels) {
  struct Case {
    std::string name;
    int spp;
    double adaptive;
    std::uint64_t seed;
  };
  const Case cases[] = {{"spp 1", 1, 0.0, 0},
                        {"spp 4", 4, 0.0, 0},
                        {"spp 4 seed 9", 4, 0.0, 9},
                        {"adaptive spp 16", 16, 0.02, 0},
                        {"adaptive spp 16 seed 5", 16, 0.05, 5}};
  const int width = 48, height = 36;
  std::vector<PixelRegion> regions = {{0, 0, width, height},  {5, 3, 37, 29},
                                      {0, 20, width, height}, {width - 1, 0, width, 1},
                                      {17, 11, 18, 12},       {30, 0, width, 9}};
  for (int i = 0; i < 4; ++i) regions.push_back(imageTile(width, height, i, 4));
  for (const scene::Scene& s : {defaultScene(), glassAndMirror()}) {
    RenderScene compiled(s);
    for (const Case& c : cases) {
      RenderSettings settings;
      settings.width = width;
      settings.height = height;
      settings.samplesPerPixel = c.spp;
      settings.adaptiveThreshold = c.adaptive;
      settings.seed = c.seed;
      settings.coverage = true;
      settings.threads = 2;
      Image full = renderImage(compiled, settings);
      for (const PixelRegion& region : regions) {
        settings.region = region;
        Image part = renderImage(compiled, settings);
        ASSERT_EQ(part.originX, region.x0);
        ASSERT_EQ(part.originY, region.y0);
        ASSERT_EQ(part.width, region.width());
        ASSERT_EQ(part.height, region.height());
        expectSamePixels(full, part,
                         c.name + ", region " + std::to_string(region.x0) + "," +
                             std::to_string(region.y0) + "," + std::to_string(region.x1) + "," +
                             std::to_string(region.y1));
      }
    }
  }
}

}  // namespace
}  // namespace render
