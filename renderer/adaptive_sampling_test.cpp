#include "renderer/adaptive_sampling.h"

#include <gtest/gtest.h>

#include "renderer/default_scene.h"
#include "renderer/render.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

TEST(AdaptiveSampling, SamplesDifferByColourOrByObject) {
  SampleLook grey = lookOf(glm::dvec3(0.5), 3);
  EXPECT_FALSE(looksDiffer(grey, lookOf({0.5, 0.5, 0.55}, 3), 0.1));
  EXPECT_TRUE(looksDiffer(grey, lookOf({0.5, 0.5, 0.65}, 3), 0.1));
  // Another object of the same colour: an edge that colours alone miss.
  EXPECT_TRUE(looksDiffer(grey, lookOf(glm::dvec3(0.5), 4), 0.1));
  EXPECT_TRUE(looksDiffer(grey, lookOf(glm::dvec3(0.5), RaySource::kNone), 0.1));
  // In the image's units: anything above 1 shows as 1.
  EXPECT_FALSE(looksDiffer(lookOf(glm::dvec3(2.0), 1), lookOf(glm::dvec3(7.0), 1), 0.01));
}

TEST(AdaptiveSampling, ASpreadExceedsWhereAnyTwoSamplesDiffer) {
  SampleSpread spread;
  spread.add(lookOf({0.2, 0.5, 0.5}, 1));
  spread.add(lookOf({0.25, 0.5, 0.5}, 1));
  EXPECT_FALSE(spread.exceeds(0.1));
  spread.add(lookOf({0.35, 0.5, 0.5}, 1));
  EXPECT_TRUE(spread.exceeds(0.1));  // 0.2 and 0.35
  SampleSpread objects;
  objects.add(lookOf(glm::dvec3(0.5), 1));
  objects.add(lookOf(glm::dvec3(0.5), 2));
  EXPECT_TRUE(objects.exceeds(0.9));
}

TEST(AdaptiveSampling, LevelsEndAtTheSamplesPerPixel) {
  EXPECT_TRUE(refinementLevels(1, 4).empty());
  EXPECT_EQ(refinementLevels(4, 4), std::vector<int>{4});
  EXPECT_EQ(refinementLevels(16, 4), (std::vector<int>{4, 16}));
  EXPECT_EQ(refinementLevels(16, 0), std::vector<int>{16});
  EXPECT_EQ(refinementLevels(2, 4), std::vector<int>{2});
}

RenderSettings adaptiveSettings(int spp, double threshold) {
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = spp;
  settings.adaptiveThreshold = threshold;
  settings.coverage = true;
  return settings;
}

TEST(AdaptiveSampling, TheSameImageAtAnyThreadCount) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(16, 0.02);
  settings.seed = 3;
  settings.threads = 1;
  Image one = renderImage(compiled, settings);
  for (int threads : {2, 3}) {
    settings.threads = threads;
    Image many = renderImage(compiled, settings);
    ASSERT_EQ(one.rgb, many.rgb) << threads << " threads";
    ASSERT_EQ(one.coverage, many.coverage) << threads << " threads";
  }
}

// Each pixel is its centre sample (uniform 1 spp) or one of its levels'
// stratified sets, exactly the pixel uniform sampling gives at that count.
TEST(AdaptiveSampling, EachPixelIsTheUniformPixelOfOneLevel) {
  RenderScene compiled(defaultScene());
  for (int first : {0, 4}) {
    RenderSettings settings = adaptiveSettings(16, 0.02);
    settings.adaptiveFirstLevel = first;
    RenderStatistics statistics;
    Image adaptive = renderImage(compiled, settings, &statistics);
    std::vector<Image> uniform;
    for (int spp : {1, 4, 16}) {
      RenderSettings u = settings;
      u.adaptiveThreshold = 0.0;
      u.samplesPerPixel = spp;
      uniform.push_back(renderImage(compiled, u));
    }
    std::size_t pixels = adaptive.coverage.size(), fromCentre = 0, fromFull = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
      auto same = [&](const Image& u) {
        return u.rgb[3 * p] == adaptive.rgb[3 * p] && u.rgb[3 * p + 1] == adaptive.rgb[3 * p + 1] &&
               u.rgb[3 * p + 2] == adaptive.rgb[3 * p + 2] && u.coverage[p] == adaptive.coverage[p];
      };
      bool centre = same(uniform[0]), four = first == 4 && same(uniform[1]),
           full = same(uniform[2]);
      ASSERT_TRUE(centre || four || full) << "pixel " << p;
      fromCentre += centre ? 1 : 0;
      fromFull += full && !centre ? 1 : 0;
    }
    EXPECT_GT(fromCentre, pixels / 2);
    EXPECT_GT(fromFull, 0u);
    EXPECT_EQ(statistics.pixels, pixels);
    EXPECT_GE(statistics.refinedPixels, statistics.fullySampledPixels);
    EXPECT_GE(statistics.fullySampledPixels, fromFull);
    EXPECT_LT(statistics.samples, 16 * pixels);
    EXPECT_GT(statistics.samples, pixels);
  }
}

TEST(AdaptiveSampling, OneSampleAPixelRefinesNothing) {
  RenderScene compiled(defaultScene());
  RenderSettings settings = adaptiveSettings(1, 0.01);
  RenderStatistics statistics;
  Image adaptive = renderImage(compiled, settings, &statistics);
  settings.adaptiveThreshold = 0.0;
  EXPECT_EQ(adaptive.rgb, renderImage(compiled, settings).rgb);
  EXPECT_EQ(statistics.refinedPixels, 0u);
  EXPECT_EQ(statistics.samples, statistics.pixels);
}

// A sphere before a wall of nearly its colour: the two differ by far less
// than the threshold, and only the change of object shows the edge.
scene::Scene sphereOnWallOfItsColour() {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere, {}, flat({0.5, 0.5, 0.5})));
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(20, 20, 1), translate(0, 0, -3)}, flat({0.5, 0.5, 0.502})));
  s.lights.push_back(light({0, 0, 5}));
  return s;
}

TEST(AdaptiveSampling, RefinesAnEdgeBetweenObjectsOfOneColour) {
  scene::Scene s = sphereOnWallOfItsColour();
  RenderScene compiled(s);
  RenderSettings settings = adaptiveSettings(16, 0.1);
  settings.coverage = false;
  RenderStatistics statistics;
  Image adaptive = renderImage(compiled, settings, &statistics);
  settings.adaptiveThreshold = 0.0;
  settings.samplesPerPixel = 1;
  Image centres = renderImage(compiled, settings);
  std::vector<std::int32_t> ids = renderObjectIds(compiled, settings);
  auto id = [&](int i, int j) { return ids[static_cast<std::size_t>(j) * settings.width + i]; };
  // Every pixel that changed lies beside the sphere's silhouette, and some do.
  int changed = 0;
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      std::size_t p = 3 * (static_cast<std::size_t>(j) * settings.width + i);
      if (adaptive.rgb[p + 2] == centres.rgb[p + 2]) continue;
      ++changed;
      bool edge = (i > 0 && id(i - 1, j) != id(i, j)) ||
                  (i + 1 < settings.width && id(i + 1, j) != id(i, j)) ||
                  (j > 0 && id(i, j - 1) != id(i, j)) ||
                  (j + 1 < settings.height && id(i, j + 1) != id(i, j));
      EXPECT_TRUE(edge) << i << "," << j;
    }
  }
  EXPECT_GT(changed, 8);
  EXPECT_GT(statistics.refinedPixels, 0u);

  // Without the sphere nothing differs, and nothing is refined.
  s.objects.erase(s.objects.begin());
  settings.adaptiveThreshold = 0.1;
  settings.samplesPerPixel = 16;
  renderImage(RenderScene(s), settings, &statistics);
  EXPECT_EQ(statistics.refinedPixels, 0u);
}

// The coverage of a pixel is the share of the samples its colour is the mean
// of: the wall's edge down the middle of column 4 covers half of it.
TEST(AdaptiveSampling, CoverageIsTheShareOfTheSamplesTraced) {
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(10, 10, 1), translate(10, 0, -5)}, flat({0.8, 0.4, 0.2})));
  s.lights.push_back(light({0, 0, 0}));
  RenderScene compiled(s);
  RenderSettings settings = adaptiveSettings(16, 0.05);
  settings.width = 9;
  settings.height = 5;
  Image image = renderImage(compiled, settings);
  for (int j = 0; j < settings.height; ++j) {
    for (int i = 0; i < settings.width; ++i) {
      float expected = i < 4 ? 0.0f : i == 4 ? 0.5f : 1.0f;
      float alpha = image.coverage[static_cast<std::size_t>(j) * settings.width + i];
      ASSERT_EQ(alpha, expected) << i << "," << j;
      ASSERT_FLOAT_EQ(image.pixel(i, j).x, 0.8f * expected) << i << "," << j;
    }
  }
}

}  // namespace
}  // namespace render
