#include "renderer/render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <set>

#include "renderer/camera.h"
#include "renderer/default_scene.h"
#include "renderer/test_scenes.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

TEST(Render, TheSameImageAtAnyThreadCount) {
  RenderScene compiled(defaultScene());
  RenderSettings settings;
  settings.width = 96;
  settings.height = 64;
  settings.samplesPerPixel = 4;
  settings.seed = 17;
  settings.threads = 1;
  Image one = renderImage(compiled, settings);
  for (int threads : {2, 3, 8}) {
    settings.threads = threads;
    Image many = renderImage(compiled, settings);
    ASSERT_EQ(one.rgb, many.rgb) << threads << " threads";
  }
  // Another seed moves the samples, and so the image.
  settings.seed = 18;
  EXPECT_NE(renderImage(compiled, settings).rgb, one.rgb);
}

TEST(Render, ACancelFlagStopsTheRenderAndNothingComesBack) {
  RenderScene compiled(defaultScene());
  RenderSettings settings;
  settings.width = 256;
  settings.height = 192;  // 8 x 6 tiles of 32
  settings.threads = 2;
  // Set before the render: no tile is finished.
  CancelFlag before;
  before.request();
  int finished = 0;
  auto count = [&finished](int, int) { ++finished; };
  EXPECT_THROW(renderImage(compiled, settings, nullptr, count, &before), RenderCancelled);
  EXPECT_EQ(finished, 0);
  // Set from the progress callback after the first tile: the threads stop
  // at their next row, well before the 48 tiles are done.
  CancelFlag during;
  finished = 0;
  auto cancelAtFirst = [&](int, int) {
    ++finished;
    during.request();
  };
  EXPECT_THROW(renderImage(compiled, settings, nullptr, cancelAtFirst, &during), RenderCancelled);
  EXPECT_GE(finished, 1);
  EXPECT_LE(finished, 2) << "a tile finished after the request";
  // A flag that is never set changes nothing.
  CancelFlag never;
  EXPECT_EQ(renderImage(compiled, settings, nullptr, {}, &never).rgb,
            renderImage(compiled, settings).rgb);
}

TEST(Render, OneSamplePassesThroughThePixelCentre) {
  EXPECT_EQ(samplePosition(3, 7, 0, 1, 99), glm::dvec2(3.5, 7.5));
  // The camera ray of pixel (i, j) at the centre of a 2x2 image looks along
  // forward exactly when the image centre is the pixel corner.
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  RenderSettings settings;
  settings.width = 2;
  settings.height = 2;
  PinholeCamera camera(s.camera, settings);
  EXPECT_EQ(camera.rayThrough(1.0, 1.0).direction, glm::dvec3(0, 0, -1));
  // Pixel (0, 0) is up and to the left; the vertical field of view is 60
  // degrees, so its centre ray is tan(30)/2 up.
  glm::dvec3 d = camera.rayThrough(0.5, 0.5).direction;
  EXPECT_LT(d.x, 0.0);
  EXPECT_GT(d.y, 0.0);
  EXPECT_NEAR(d.y / -d.z, std::tan(3.141592653589793 / 6) / 2, 1e-15);
}

TEST(Render, CameraAxesOfAnyFiniteLengthGiveTheSameRays) {
  // A rotated camera whose axes are scaled by 1e-300, 1e300 and the largest
  // double: each is valid (FORMATS.md), and the plain normalisation would
  // underflow or overflow on every one.
  scene::Scene s = sceneLookingAt({1, 2, 3}, {-2, 0.5, -1});
  RenderSettings settings;
  settings.width = 8;
  settings.height = 6;
  PinholeCamera unit(s.camera, settings);
  for (double scale : {1e-300, 1e300, 1.7976931348623157e308}) {
    SCOPED_TRACE(scale);
    scene::Camera scaled = s.camera;
    for (int c = 0; c < 3; ++c) scaled.matrix[c] *= scale;
    PinholeCamera camera(scaled, settings);
    for (double x : {0.5, 3.5, 7.5}) {
      for (double y : {0.5, 5.5}) {
        glm::dvec3 a = unit.rayThrough(x, y).direction;
        glm::dvec3 b = camera.rayThrough(x, y).direction;
        ASSERT_NEAR(glm::length(a - b), 0.0, 1e-14) << x << " " << y;
      }
    }
  }
}

TEST(Render, SamplesAreStratified) {
  // A power of two of samples, 4^k, puts one in each cell of a 2^k x 2^k
  // grid (PixelSampleSequence's nets; its tests check every split).
  for (int count : {4, 16, 64}) {
    std::set<std::pair<int, int>> cells;
    int columns = static_cast<int>(std::lround(std::sqrt(count)));
    int rows = columns;
    for (int k = 0; k < count; ++k) {
      glm::dvec2 p = samplePosition(10, 20, k, count, 5);
      ASSERT_GE(p.x, 10.0);
      ASSERT_LT(p.x, 11.0);
      ASSERT_GE(p.y, 20.0);
      ASSERT_LT(p.y, 21.0);
      cells.insert({static_cast<int>((p.x - 10) * columns), static_cast<int>((p.y - 20) * rows)});
    }
    EXPECT_EQ(cells.size(), static_cast<std::size_t>(count)) << "one sample per cell";
  }
}

TEST(Render, NoPixelIsEverNanOrInfinite) {
  // Lights far brighter than a float holds, a camera inside glass, a
  // degenerate grazing plane, mirrors facing each other.
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0.1, -1});
  scene::Material glass;
  glass.transparency = 1.0;
  glass.reflectivity = 1.0;
  glass.ri = 1.7;
  s.objects.push_back(object(ObjectKind::Sphere, {scale(3)}, glass));
  scene::Material mirror;
  mirror.reflectivity = 1.0;
  mirror.shininess = 1e-300;
  s.objects.push_back(object(ObjectKind::Cube, {scale(10, 0.1, 10), translate(0, -1, 0)}, mirror));
  s.objects.push_back(object(ObjectKind::Plane, {}, mirror));
  s.lights.push_back(light({1, 1, 1}, glm::dvec3(1e300)));
  s.lights.push_back(light({0, 0, 0}, glm::dvec3(1e300)));
  RenderScene compiled(s);
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = 4;
  Image image = renderImage(compiled, settings);
  for (float v : image.rgb) ASSERT_TRUE(std::isfinite(v));
}

TEST(Render, CountsItsRays) {
  RenderScene compiled(defaultScene());
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.samplesPerPixel = 2;
  RenderStatistics statistics;
  renderImage(compiled, settings, &statistics);
  EXPECT_EQ(statistics.rays.primary, 40u * 30u * 2u);
  EXPECT_GT(statistics.rays.shadow, 0u);
  EXPECT_GT(statistics.rays.secondary, 0u);
}

TEST(Render, ObjectIdsFollowThePixelCentres) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.objects.push_back(object(ObjectKind::Sphere));
  RenderSettings settings;
  settings.width = 64;
  settings.height = 64;
  std::vector<std::int32_t> ids = renderObjectIds(RenderScene(s), settings);
  EXPECT_EQ(ids[32 * 64 + 32], 0);  // the middle
  EXPECT_EQ(ids[0], -1);            // the corner
}

// A wall whose left edge, seen from the eye, runs down the middle of the
// middle column of a 9-pixel-wide image: x = 4.5, where the camera ray has
// no sideways part.
scene::Scene halfCoveredColumn() {
  scene::Scene s = sceneLookingAt({0, 0, 0}, {0, 0, -1});
  s.objects.push_back(
      object(ObjectKind::Cube, {scale(10, 10, 1), translate(10, 0, -5)}, flat({0.8, 0.4, 0.2})));
  s.lights.push_back(light({0, 0, 0}));
  return s;
}

TEST(Render, CoverageIsTheShareOfSamplesThatMeetAnObject) {
  RenderScene compiled(halfCoveredColumn());
  RenderSettings settings;
  settings.width = 9;
  settings.height = 5;
  settings.coverage = true;
  for (int spp : {4, 16}) {
    settings.samplesPerPixel = spp;
    Image image = renderImage(compiled, settings);
    ASSERT_EQ(image.coverage.size(), 9u * 5u);
    for (int j = 0; j < settings.height; ++j) {
      for (int i = 0; i < settings.width; ++i) {
        float expected = i < 4 ? 0.0f : i == 4 ? 0.5f : 1.0f;
        float alpha = image.coverage[static_cast<std::size_t>(j) * settings.width + i];
        ASSERT_EQ(alpha, expected) << i << "," << j << " at " << spp << " spp";
        // The colour is the coverage times the wall's: premultiplied.
        ASSERT_FLOAT_EQ(image.pixel(i, j).x, 0.8f * expected) << i << "," << j;
      }
    }
  }
}

TEST(Render, CoverageChangesNoColour) {
  RenderScene compiled(defaultScene());
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = 2;
  Image plain = renderImage(compiled, settings);
  EXPECT_TRUE(plain.coverage.empty());
  settings.coverage = true;
  Image covered = renderImage(compiled, settings);
  EXPECT_EQ(plain.rgb, covered.rgb);
  ASSERT_EQ(covered.coverage.size(), 64u * 48u);
  // The default scene's floor fills the bottom row, the sky the top one.
  EXPECT_EQ(covered.coverage.back(), 1.0f);
  EXPECT_EQ(covered.coverage.front(), 0.0f);
}

}  // namespace
}  // namespace render
