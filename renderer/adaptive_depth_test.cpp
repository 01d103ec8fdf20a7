// Adaptive depth control (docs/RENDERING.md, "Cost"): the bound on what a
// ray brings back, the error that leaving branches out makes, and the work
// it saves where every hit both reflects and refracts.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/camera.h"
#include "renderer/default_scene.h"
#include "renderer/radiance_bound.h"
#include "renderer/render.h"
#include "renderer/test_scenes.h"
#include "renderer/tracer.h"

namespace render {
namespace {

using namespace render::testing;
using scene::ObjectKind;

constexpr double kHalfLevel = 0.5 / 255.0;

scene::Material glassMirror(const glm::dvec3& colour, double reflectivity = 0.5,
                            double transparency = 0.5) {
  scene::Material m;
  m.colour = colour;
  m.reflectivity = reflectivity;
  m.transparency = transparency;
  m.ri = 1.5;
  return m;
}

// The scene of testdata/render-cost/glass-room.txt: four spheres that
// reflect and refract inside a closed cube that does too, so that almost
// every ray meets something and every hit spawns two rays.
scene::Scene glassRoom(double reflectivity = 0.5, double transparency = 0.5) {
  scene::Scene s = sceneLookingAt({0, 0, 6}, {0, 0, 0});
  s.lights.push_back(light({3, 5, 5}));
  s.objects.push_back(object(ObjectKind::Cube, {scale(10)},
                             glassMirror({0.8, 0.8, 0.8}, reflectivity, transparency)));
  const glm::dvec3 centres[] = {{-1.1, -0.6, 0}, {1.1, -0.6, 0}, {0, 1.3, 0}, {0, 0, -2}};
  const glm::dvec3 colours[] = {{0.9, 0.2, 0.2}, {0.2, 0.9, 0.2}, {0.2, 0.2, 0.9}, {1, 1, 1}};
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3& c = centres[i];
    s.objects.push_back(object(ObjectKind::Sphere, {translate(c.x, c.y, c.z)},
                               glassMirror(colours[i], reflectivity, transparency)));
  }
  return s;
}

struct Traced {
  glm::dvec3 colour;
  RayCounts counts;
};

Traced traceOne(const Tracer& tracer, const Ray& ray, double tolerance) {
  MediumStack media;
  TraceContext context;
  Traced t;
  t.colour = tracer.trace(ray, RaySource{}, 0, media, context, tolerance);
  t.counts = context.counts;
  return t;
}

// Rays from the scene's eye through random points of a 60-degree cone.
std::vector<Ray> randomRays(const scene::Scene& s, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  PinholeCamera camera(s.camera, RenderSettings{});
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    rays.push_back(camera.rayThrough(320 + 640 * u(rng), 240 + 480 * u(rng)));
  }
  return rays;
}

TEST(RadianceBound, SurfaceAndWeightByHand) {
  scene::Scene s = sceneLookingAt({0, 0, 5}, {0, 0, 0});
  s.lights.push_back(light({0, 5, 0}, {1, 2, 0.5}));
  scene::Material m = glassMirror({0.5, 1, 1}, 0.3, 0.6);
  m.ambient = 0.1;
  m.diffuse = 0.9;
  m.specular = 0.5;
  s.objects.push_back(object(ObjectKind::Sphere, {}, m));
  RadianceBound bound(RenderScene(s), 5);
  // The green channel: 2 * (1 * (0.1 + 0.9) + 0.5) = 3; a solid that both
  // reflects and refracts passes on at most the larger of the two.
  EXPECT_NEAR(bound.surface(), 3.0, 1e-5);
  EXPECT_NEAR(bound.branchWeight(), 0.6, 1e-8);
  EXPECT_EQ(bound.at(6), 0.0);  // past the limit: black
  EXPECT_EQ(bound.at(5), bound.surface());
  EXPECT_DOUBLE_EQ(bound.at(4), bound.surface() * (1 + bound.branchWeight()));
  EXPECT_LT(bound.at(0), bound.surface() / (1 - bound.branchWeight()));

  // A plane that has both passes TRANSPARENCY on (its reflectance is 0); a
  // mirror, its REFLECTIVITY; without any light nothing is lit at all.
  s.objects[0].kind = ObjectKind::Plane;
  EXPECT_NEAR(RadianceBound(RenderScene(s), 5).branchWeight(), 0.6, 1e-8);
  s.objects[0].material.transparency = 0.0;
  EXPECT_NEAR(RadianceBound(RenderScene(s), 5).branchWeight(), 0.3, 1e-8);
  s.lights.clear();
  EXPECT_EQ(RadianceBound(RenderScene(s), 5).at(0), 0.0);
}

TEST(RadianceBound, NoneOutsideTheRangesOrOnOverflow) {
  scene::Scene s = glassRoom();
  EXPECT_TRUE(RadianceBound(RenderScene(s), 5).bounded());
  scene::Scene negative = s;
  negative.lights[0].colour.g = -1.0;
  scene::Scene notANumber = s;
  notANumber.objects[1].material.diffuse = std::nan("");
  scene::Scene huge = s;
  huge.lights.push_back(light({0, 0, 0}, glm::dvec3(1.7e308)));
  for (const scene::Scene& bad : {negative, notANumber, huge}) {
    RadianceBound bound(RenderScene(bad), 5);
    EXPECT_FALSE(bound.bounded());
    EXPECT_EQ(bound.at(0), RadianceBound::kUnbounded);
    EXPECT_EQ(bound.at(9), RadianceBound::kUnbounded);  // not even 0 past the limit
  }
}

TEST(RadianceBound, HoldsForEveryRayTracedInFull) {
  for (const scene::Scene& s : {defaultScene(), glassRoom(), glassRoom(1.0, 1.0)}) {
    RenderScene compiled(s);
    Tracer tracer(compiled, 6);
    for (const Ray& ray : randomRays(s, 200, 7)) {
      Traced full = traceOne(tracer, ray, 0.0);
      for (int c = 0; c < 3; ++c) {
        ASSERT_GE(full.colour[c], 0.0);
        ASSERT_LE(full.colour[c], tracer.bound().at(0));
      }
    }
  }
}

TEST(AdaptiveDepth, TheErrorStaysWithinTheTolerance) {
  // Depth 12 is still quick to trace in full. Leaving out branches only
  // drops terms that are not negative, so the colour can only go down. At
  // half a level, branches go only some ten splits deep (the tolerance
  // doubles at each), where they make no difference here.
  scene::Scene s = glassRoom();
  RenderScene compiled(s);
  Tracer tracer(compiled, 12);
  std::uint64_t pruned = 0;
  for (double tolerance : {kHalfLevel, 0.05, 0.5}) {
    double worst = 0.0;
    for (const Ray& ray : randomRays(s, 150, 11)) {
      Traced full = traceOne(tracer, ray, 0.0);
      Traced cut = traceOne(tracer, ray, tolerance);
      pruned += cut.counts.pruned;
      ASSERT_LE(cut.counts.secondary, full.counts.secondary);
      for (int c = 0; c < 3; ++c) {
        double error = full.colour[c] - cut.colour[c];
        ASSERT_GE(error, -1e-12) << tolerance;
        ASSERT_LE(error, tolerance) << tolerance;
        worst = std::max(worst, error);
      }
    }
    if (tolerance > kHalfLevel) {
      EXPECT_GT(worst, 0.0) << tolerance;
    }
  }
  EXPECT_GT(pruned, 0u);
}

TEST(AdaptiveDepth, ToleranceZeroChangesNothing) {
  // Only branches of weight 0 (a plane's reflection, which its reflectance
  // of 0 takes away) and those past the depth limit are left out: the
  // colour is the same to the last bit as that of a plane that does not
  // reflect at all, which never had the branch.
  scene::Scene s = glassRoom();
  s.objects.push_back(
      object(ObjectKind::Plane, {translate(0, -2, 0)}, glassMirror({0.3, 0.3, 0.3})));
  scene::Scene sheet = s;
  sheet.objects.back().material.reflectivity = 0.0;
  RenderScene compiled(s);
  RenderScene compiledSheet(sheet);
  for (int depth : {0, 3}) {
    Tracer tracer(compiled, depth);
    Tracer sheetTracer(compiledSheet, depth);
    std::uint64_t pruned = 0;
    for (const Ray& ray : randomRays(s, 100, 3)) {
      Traced a = traceOne(tracer, ray, 0.0);
      Traced b = traceOne(sheetTracer, ray, 0.0);
      pruned += a.counts.pruned;
      ASSERT_EQ(a.colour, b.colour);
    }
    EXPECT_GT(pruned, 0u);
  }
}

// Secondary rays per primary ray, at most, for a scene whose hits pass on at
// most K of what their children bring and whose rays bring at most M: a
// path holds at most ceil(log(M / tolerance) / log(1 / K)) - 1 hits whose
// two children are both traced, so at most 2^that paths of depth + 1 rays.
double secondaryBound(const RadianceBound& bound, int depth, double tolerance, double k) {
  double splits = std::ceil(std::log(bound.at(1) / tolerance) / std::log(1.0 / k)) - 1.0;
  return std::min(std::pow(2.0, depth + 1), (depth + 1) * std::pow(2.0, splits));
}

TEST(AdaptiveDepth, TheWorkIsBoundedWhereEveryHitSplits) {
  // Traced in full, a ray of this scene takes 218 rays on average and up to
  // 2,454 at depth 20, and some 1.23 times as many at each further bounce:
  // at depth 64 it never ends. With adaptive depth control, a few hundred
  // at most, at depth 20 as at 64.
  scene::Scene s = glassRoom();
  RenderScene compiled(s);
  for (int depth : {20, 64}) {
    Tracer tracer(compiled, depth);
    double bound = secondaryBound(tracer.bound(), depth, kHalfLevel, 0.5);
    std::uint64_t most = 0;
    for (const Ray& ray : randomRays(s, 100, 5)) {
      Traced cut = traceOne(tracer, ray, kHalfLevel);
      most = std::max(most, cut.counts.secondary);
    }
    EXPECT_LE(static_cast<double>(most), bound) << depth;
    EXPECT_LE(most, 1000u) << depth;
  }
}

TEST(AdaptiveDepth, TheAllowanceBoundsTheWorkOfAnyScene) {
  // Where every hit passes on nearly all it receives, no tolerance bounds
  // the work: the allowance does, and the heavier branch goes first.
  for (double share : {0.9, 1.0}) {
    scene::Scene s = glassRoom(share, share);
    RenderScene compiled(s);
    Tracer tracer(compiled, 64);
    std::uint64_t cut = 0;
    for (const Ray& ray : randomRays(s, 20, 5)) {
      MediumStack media;
      TraceContext context;
      context.allowance = 4096;
      tracer.trace(ray, RaySource{}, 0, media, context, kHalfLevel);
      ASSERT_LE(context.counts.secondary, 4096u);
      cut += context.counts.cut;
    }
    EXPECT_GT(cut, 0u) << share;
  }
}

TEST(AdaptiveDepth, TheAllowanceIsPerSample) {
  // The same image whatever the thread count, and with an allowance large
  // enough to never run out (at depth 12 a sample takes 567 rays at most,
  // retraced pixels included), the same as without one.
  RenderScene compiled(glassRoom());
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.maxDepth = 12;
  settings.threads = 1;
  RenderStatistics one;
  Image image = renderImage(compiled, settings, &one);
  EXPECT_EQ(one.rays.cut, 0u);
  settings.threads = 3;
  EXPECT_EQ(renderImage(compiled, settings).rgb, image.rgb);
  settings.maxRaysPerSample = 1 << 20;
  EXPECT_EQ(renderImage(compiled, settings).rgb, image.rgb);
  settings.maxRaysPerSample = 16;
  RenderStatistics small;
  Image cut = renderImage(compiled, settings, &small);
  EXPECT_GT(small.rays.cut, 0u);
  // 16 a sample, and a retraced pixel has its samples traced up to twice
  // more.
  EXPECT_LE(small.rays.secondary, 16u * (48u * 32u + 2u * small.retracedPixels));
  EXPECT_NE(cut.rgb, image.rgb);
}

TEST(AdaptiveDepth, TheImageIsTheSameToTheLastLevel) {
  // The default scene at the default depth and at 12, and the glass room at
  // 12 (where, without the retracing of pixels whose level the left-out
  // branches could move, 235 of 230,400 channels came out one level low):
  // every 8-bit level is what tracing in full gives, and no float moves by
  // half a level.
  struct Case {
    scene::Scene scene;
    int depth;
  };
  for (const Case& test :
       {Case{defaultScene(), 5}, Case{defaultScene(), 12}, Case{glassRoom(), 12}}) {
    RenderScene compiled(test.scene);
    RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.maxDepth = test.depth;
    settings.samplesPerPixel = 2;
    RenderStatistics cutStatistics, fullStatistics;
    Image cut = renderImage(compiled, settings, &cutStatistics);
    settings.pruneTolerance = 0.0;
    Image full = renderImage(compiled, settings, &fullStatistics);
    EXPECT_EQ(fullStatistics.retracedPixels, 0u);
    auto level = [](float v) { return std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f); };
    for (std::size_t i = 0; i < full.rgb.size(); ++i) {
      ASSERT_LE(std::abs(full.rgb[i] - cut.rgb[i]), kHalfLevel) << i;
      ASSERT_EQ(level(full.rgb[i]), level(cut.rgb[i])) << i;
    }
    EXPECT_LT(cutStatistics.rays.secondary, fullStatistics.rays.secondary) << test.depth;
  }
}

TEST(AdaptiveDepth, A16BitImageIsTheSameToTheLastLevel) {
  // With the levels of a 16-bit image and half of one of them as the
  // tolerance, every 16-bit level is what tracing in full gives; with the
  // 8-bit settings, some are not.
  RenderScene compiled(glassRoom());
  RenderSettings settings;
  settings.width = 80;
  settings.height = 60;
  settings.maxDepth = 12;
  Image cut8 = renderImage(compiled, settings);
  settings.levels = 65535.0;
  settings.pruneTolerance = 0.5 / settings.levels;
  Image cut16 = renderImage(compiled, settings);
  settings.pruneTolerance = 0.0;
  Image full = renderImage(compiled, settings);
  auto level = [](float v) { return std::lround(std::clamp(double{v}, 0.0, 1.0) * 65535.0); };
  int differ8 = 0;
  for (std::size_t i = 0; i < full.rgb.size(); ++i) {
    ASSERT_LE(std::abs(full.rgb[i] - cut16.rgb[i]), 0.5 / 65535.0) << i;
    ASSERT_EQ(level(full.rgb[i]), level(cut16.rgb[i])) << i;
    differ8 += level(full.rgb[i]) != level(cut8.rgb[i]) ? 1 : 0;
  }
  EXPECT_GT(differ8, 0);
}

}  // namespace
}  // namespace render
