#include "renderer/material_maxima.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace render {
namespace {

using scene::ObjectKind;

// The surface bound as one pass over the objects in order gives it, the
// way RadianceBound took it before the maxima were gathered: each object's
// term times each light channel, the largest kept.
double surfaceInOnePass(const std::vector<scene::Material>& materials, const glm::dvec3& lights) {
  double surface = 0.0;
  for (const scene::Material& m : materials) {
    double highlight = std::pow(MaterialMaxima::kUnitDotMax, m.shininess);
    for (int c = 0; c < 3; ++c) {
      double term =
          lights[c] * (m.colour[c] * (m.ambient + m.diffuse * MaterialMaxima::kUnitDotMax) +
                       m.specular * highlight);
      surface = std::max(surface, term);
    }
  }
  return surface;
}

// Values spread over many sizes, some of them overflowing in the product,
// and zeros.
double anyValue(std::mt19937_64& random) {
  std::uniform_int_distribution<int> pick(0, 9);
  int kind = pick(random);
  if (kind == 0) return 0.0;
  if (kind == 1) return std::numeric_limits<double>::max() / 4;
  std::uniform_real_distribution<double> exponent(-8.0, 8.0);
  return std::uniform_real_distribution<double>(0.0, 1.0)(random) *
         std::pow(10.0, exponent(random));
}

TEST(MaterialMaxima, GatheredInPartsTheyBoundAsOnePassInOrderDoes) {
  std::mt19937_64 random(20261205);
  for (int round = 0; round < 300; ++round) {
    std::vector<scene::Material> materials(1 + random() % 40);
    for (scene::Material& m : materials) {
      m.colour = {anyValue(random), anyValue(random), anyValue(random)};
      m.ambient = anyValue(random);
      m.diffuse = anyValue(random);
      m.specular = anyValue(random);
      // Shininess shared by neighbours, as files mostly have it, and
      // large enough at times for its highlight to overflow.
      m.shininess = random() % 3 == 0 ? 5e16 : static_cast<double>(random() % 4) * 50.0;
      m.reflectivity = anyValue(random);
      m.transparency = random() % 2 ? 0.0 : anyValue(random);
    }
    glm::dvec3 lights(random() % 4 == 0 ? 0.0 : anyValue(random), anyValue(random),
                      anyValue(random));
    std::size_t cut = random() % (materials.size() + 1);
    MaterialMaxima first, second, whole;
    for (std::size_t k = 0; k < materials.size(); ++k) {
      (k < cut ? first : second).add(ObjectKind::Sphere, materials[k]);
      whole.add(ObjectKind::Sphere, materials[k]);
    }
    // Merged in either order.
    MaterialMaxima merged = second;
    merged.merge(first);
    first.merge(second);
    for (const MaterialMaxima* maxima : {&first, &merged, &whole}) {
      ASSERT_TRUE(maxima->inRange());
      double surface = 0.0;
      for (int c = 0; c < 3; ++c) {
        surface = std::max(surface, lights[c] * maxima->surfaceFactor()[c]);
      }
      // Bit for bit: the light's channel, not negative, keeps the order.
      EXPECT_EQ(surface, surfaceInOnePass(materials, lights)) << "round " << round;
    }
    double weight = 0.0;
    for (const scene::Material& m : materials) {
      weight = std::max(weight, m.transparency > 0.0 && m.reflectivity > 0.0
                                    ? std::max(m.reflectivity, m.transparency)
                                    : m.reflectivity + m.transparency);
    }
    EXPECT_EQ(first.branchWeight(), weight);
    EXPECT_EQ(merged.branchWeight(), weight);
  }
}

TEST(MaterialMaxima, OneMaterialOutOfRangeInAnyPartLeavesAllOutOfRange) {
  scene::Material fine;
  scene::Material negative;
  negative.diffuse = -0.5;
  scene::Material infinite;
  infinite.colour.b = std::numeric_limits<double>::infinity();
  scene::Material notANumber;
  notANumber.shininess = std::nan("");
  for (const scene::Material& bad : {negative, infinite, notANumber}) {
    MaterialMaxima a, b;
    a.add(ObjectKind::Cube, fine);
    b.add(ObjectKind::Cube, bad);
    b.add(ObjectKind::Cube, fine);
    EXPECT_TRUE(a.inRange());
    EXPECT_FALSE(b.inRange());
    a.merge(b);
    EXPECT_FALSE(a.inRange());
  }
  // A plane with both passes on its transparency alone.
  scene::Material both;
  both.reflectivity = 0.8;
  both.transparency = 0.3;
  MaterialMaxima plane, solid;
  plane.add(ObjectKind::Plane, both);
  solid.add(ObjectKind::Cylinder, both);
  EXPECT_EQ(plane.branchWeight(), 0.3);
  EXPECT_EQ(solid.branchWeight(), 0.8);
}

}  // namespace
}  // namespace render
