#include "libscene/formats/gltf/gltf_light_units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "scenefile/srgb.h"

namespace scene::gltf {
namespace {

TEST(GltfLightUnits, AReferenceSurfaceShowsTheSameDisplayValueInBothRenderers) {
  // The renderer shows a surface of COLOUR s facing a LIGHT of colour L (default
  // AMBIENT + DIFFUSE = 1) at s * L; Blender's Cycles shows linear
  // s * E / kLuxPerUnit, sRGB-encoded.
  for (double l : {0.05, 0.35, 0.8, 1.0, 1.2}) {
    glm::dvec3 lux = illuminanceFromColour(glm::dvec3(l));
    double cycles = linearToSrgb(kReferenceSurface * lux.x / kLuxPerUnit);
    EXPECT_NEAR(cycles, kReferenceSurface * l, 1e-12) << l;
  }
}

TEST(GltfLightUnits, IntensityFollowsTheSquareOfTheReferenceDistance) {
  glm::dvec3 colour(0.8, 0.4, 0.0);
  PointLight at1 = pointLightFromColour(colour, 1.0);
  PointLight at10 = pointLightFromColour(colour, 10.0);
  EXPECT_NEAR(at10.intensity / at1.intensity, 100.0, 1e-12);
  EXPECT_EQ(at1.color, at10.color);
  EXPECT_EQ(at1.color.x, 1.0);
  EXPECT_NEAR(at1.color.y, srgbToLinear(0.32) / srgbToLinear(0.64), 1e-15);
  EXPECT_EQ(at1.color.z, 0.0);
  EXPECT_NEAR(at1.intensity, srgbToLinear(0.64) / 0.8 * 683 * std::numbers::pi, 1e-9);
  EXPECT_FALSE(at10.clamped);
}

TEST(GltfLightUnits, ColourComesBackFromTheLightAtTheSameDistance) {
  for (double distance : {1e-3, 0.5, 7.0, 1e4}) {
    for (glm::dvec3 colour : {glm::dvec3(1.0), glm::dvec3(0.35, 0.35, 0.4), glm::dvec3(2.5, 0, 1),
                              glm::dvec3(1e-6, 0.02, 0.5)}) {
      glm::dvec3 back = colourFromPointLight(pointLightFromColour(colour, distance), distance);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(back[c], colour[c], 1e-12 * std::max(1.0, colour[c])) << distance;
      }
    }
  }
  PointLight black = pointLightFromColour(glm::dvec3(0.0), 3.0);
  EXPECT_EQ(black.intensity, 0.0);
  EXPECT_EQ(colourFromPointLight(black, 3.0), glm::dvec3(0.0));
}

TEST(GltfLightUnits, ABlenderLightShowsOnTheReferenceSurfaceAsInCycles) {
  // Blender exports a point light of P W as P / (4 pi) * 683 cd; Cycles
  // shows a white surface d away at P / (4 pi^2 d^2).
  double watts = 1000.0;
  PointLight blender{glm::dvec3(1.0), watts / (4 * std::numbers::pi) * 683};
  double d = 5.0;
  double cycles =
      linearToSrgb(kReferenceSurface * watts / (4 * std::numbers::pi * std::numbers::pi * d * d));
  glm::dvec3 colour = colourFromPointLight(blender, d);
  EXPECT_NEAR(kReferenceSurface * colour.x, cycles, 1e-12);
  // A 10 W light 10 away, which used to read as a colour of 543, is dim.
  EXPECT_LT(colourFromPointLight(PointLight{glm::dvec3(1.0), 543.514}, 10.0).x, 0.1);
}

TEST(GltfLightUnits, IntensityStaysWithinFloats) {
  constexpr double kLargest = std::numeric_limits<double>::max();
  PointLight huge = pointLightFromColour(glm::dvec3(kLargest, 5e-324, 0), 4.0);
  EXPECT_TRUE(huge.clamped);
  EXPECT_EQ(huge.intensity, kLargestIntensity);
  EXPECT_EQ(huge.color, glm::dvec3(1.0, 0.0, 0.0));
  PointLight far = pointLightFromColour(glm::dvec3(1.0), 1e30);
  EXPECT_TRUE(far.clamped);
  EXPECT_EQ(far.intensity, kLargestIntensity);
  PointLight faint = pointLightFromColour(glm::dvec3(1e-300), 1.0);
  EXPECT_TRUE(faint.clamped);
  EXPECT_EQ(faint.intensity, kSmallestIntensity);
  // A subnormal channel beside a larger one keeps its ratio, not NaN.
  PointLight tiny = pointLightFromColour(glm::dvec3(1.5e-323, 0, 1e-323), 1.0);
  EXPECT_EQ(tiny.color.x, 1.0);
  EXPECT_TRUE(std::isfinite(tiny.color.z));
}

TEST(GltfLightUnits, DirectionalLightsAndOldFiles) {
  // Lux needs no distance: 683 * pi lux is the colour whose display value on
  // the reference surface is the surface's linear 1 encoded.
  glm::dvec3 sun = colourFromDirectionalLight(PointLight{glm::dvec3(1.0), kLuxPerUnit});
  EXPECT_NEAR(sun.x, linearToSrgb(kReferenceSurface) / kReferenceSurface, 1e-12);
  PointLight old = unscaledPointLightFromColour(glm::dvec3(2, 1, 0.5));
  EXPECT_EQ(old.intensity, 2.0);
  EXPECT_EQ(old.color, glm::dvec3(1, 0.5, 0.25));
}

}  // namespace
}  // namespace scene::gltf
