#include "scenefile/scene_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace scene {
namespace {

Object placed(ObjectKind kind, const glm::dmat4& matrix, const glm::dvec3& colour = {1, 1, 1}) {
  Object o;
  o.kind = kind;
  o.matrix = matrix;
  o.material.colour = colour;
  return o;
}

glm::dmat4 at(double x, double y, double z) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(x, y, z, 1.0);
  return m;
}

TEST(SceneSummary, EachKindsBoxIsExact) {
  EXPECT_EQ(objectBounds(ObjectKind::Sphere, at(1, 2, 3)), (Bounds{{0, 1, 2}, {2, 3, 4}}));
  // A cube turned 45 degrees about y reaches sqrt(2) along x and z.
  glm::dmat4 turned(1.0);
  double c = std::sqrt(0.5);
  turned[0] = glm::dvec4(c, 0, -c, 0);
  turned[2] = glm::dvec4(c, 0, c, 0);
  std::optional<Bounds> cube = objectBounds(ObjectKind::Cube, turned);
  ASSERT_TRUE(cube);
  EXPECT_NEAR(cube->high.x, 2 * c, 1e-15);
  EXPECT_NEAR(cube->high.z, 2 * c, 1e-15);
  EXPECT_EQ(cube->high.y, 1.0);
  // A cylinder lying along x: its axis (y) becomes x, its discs y-z.
  glm::dmat4 lying(0.0);
  lying[0] = glm::dvec4(0, 1, 0, 0);
  lying[1] = glm::dvec4(3, 0, 0, 0);
  lying[2] = glm::dvec4(0, 0, 1, 0);
  lying[3] = glm::dvec4(0, 0, 0, 1);
  EXPECT_EQ(objectBounds(ObjectKind::Cylinder, lying), (Bounds{{-3, -1, -1}, {3, 1, 1}}));
  EXPECT_FALSE(objectBounds(ObjectKind::Plane, at(0, 0, 0)));
}

TEST(SceneSummary, CountsKindsLightsAndDistinctMaterialsAndBoundsTheFiniteObjects) {
  Scene scene;
  scene.lights.resize(2);
  scene.objects = {placed(ObjectKind::Plane, at(0, -1, 0)),
                   placed(ObjectKind::Sphere, at(0, 0, 0), {1, 0, 0}),
                   placed(ObjectKind::Sphere, at(4, 0, 0), {1, 0, 0}),
                   placed(ObjectKind::Cube, at(0, 5, 0), {0, 0, 1})};
  SceneSummary summary = summarizeScene(scene);
  EXPECT_EQ(summary.count(ObjectKind::Plane), 1u);
  EXPECT_EQ(summary.count(ObjectKind::Sphere), 2u);
  EXPECT_EQ(summary.count(ObjectKind::Cylinder), 0u);
  EXPECT_EQ(summary.count(ObjectKind::Cube), 1u);
  EXPECT_EQ(summary.lights, 2u);
  EXPECT_EQ(summary.materials, 3u);  // white, red, blue
  EXPECT_EQ(summary.bounds, (Bounds{{-1, -1, -1}, {5, 6, 1}}));
  EXPECT_EQ(summary.unbounded, 1u);
}

TEST(SceneSummary, NoBoxWithoutAFiniteObject) {
  Scene scene;
  EXPECT_FALSE(summarizeScene(scene).bounds);
  EXPECT_EQ(summarizeScene(scene).materials, 0u);
  glm::dmat4 huge = at(0, 0, 0);
  huge[0][0] = std::numeric_limits<double>::infinity();
  scene.objects = {placed(ObjectKind::Plane, at(0, 0, 0)), placed(ObjectKind::Sphere, huge)};
  SceneSummary summary = summarizeScene(scene);
  EXPECT_FALSE(summary.bounds);
  EXPECT_EQ(summary.unbounded, 2u);
}

}  // namespace
}  // namespace scene
