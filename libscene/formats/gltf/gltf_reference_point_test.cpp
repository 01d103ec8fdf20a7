#include "libscene/formats/gltf/gltf_reference_point.h"

#include <gtest/gtest.h>

#include <limits>

#include "scenefile/transform.h"

namespace scene::gltf {
namespace {

Object object(ObjectKind kind, const glm::dmat4& matrix) {
  Object o;
  o.kind = kind;
  o.matrix = matrix;
  return o;
}

glm::dmat4 placed(const glm::dvec3& at, const glm::dvec3& scale = glm::dvec3(1.0)) {
  glm::dmat4 m(1.0);
  for (int i = 0; i < 3; ++i) m[i][i] = scale[i];
  m[3] = glm::dvec4(at, 1.0);
  return m;
}

// A camera at `eye` looking at `target`.
Scene sceneLooking(const glm::dvec3& eye, const glm::dvec3& target) {
  Scene s;
  s.camera.matrix = cameraFromLookAt(eye, target);
  return s;
}

TEST(GltfReferencePoint, RayMeetsEachUnitShapeWhereItsSurfaceIs) {
  glm::dvec3 origin(0, 0, 10), down(0, 0, -1);
  auto t = [&](ObjectKind kind, const glm::dmat4& m) {
    return rayHit(object(kind, m), origin, down).value_or(-1.0);
  };
  EXPECT_DOUBLE_EQ(t(ObjectKind::Sphere, placed({0, 0, 0}, glm::dvec3(2))), 8.0);
  EXPECT_DOUBLE_EQ(t(ObjectKind::Cube, placed({0, 0, 1})), 8.0);
  // The cylinder's axis is its local Y: the ray meets its curved side.
  EXPECT_DOUBLE_EQ(t(ObjectKind::Cylinder, placed({0, 0, 0}, {3, 1, 3})), 7.0);
  // A plane turned to face the ray (its local Y along world Z).
  glm::dmat4 facing(1.0);
  facing[1] = glm::dvec4(0, 0, 1, 0);
  facing[2] = glm::dvec4(0, -1, 0, 0);
  facing[3] = glm::dvec4(0, 0, -2, 1);
  EXPECT_DOUBLE_EQ(t(ObjectKind::Plane, facing), 12.0);
  // Misses: beside the sphere, a plane the ray runs along, and behind.
  EXPECT_FALSE(rayHit(object(ObjectKind::Sphere, placed({5, 0, 0})), origin, down));
  EXPECT_FALSE(rayHit(object(ObjectKind::Plane, placed({0, 0, 0})), origin, down));
  EXPECT_FALSE(rayHit(object(ObjectKind::Cube, placed({0, 0, 20})), origin, down));
  // From inside a solid, its far side.
  EXPECT_DOUBLE_EQ(t(ObjectKind::Cube, placed({0, 0, 10})), 1.0);
}

TEST(GltfReferencePoint, IsWhereTheCameraLooksOnTheNearestObject) {
  Scene s = sceneLooking({0, 0, 10}, {0, 0, 0});
  s.objects = {object(ObjectKind::Sphere, placed({0, 0, -5})),
               object(ObjectKind::Cube, placed({0, 0, 2})),
               object(ObjectKind::Sphere, placed({5, 0, 0}))};
  ReferencePoint p = referencePoint(s);
  EXPECT_EQ(p.source, ReferencePoint::Source::CameraRay);
  EXPECT_EQ(p.point, glm::dvec3(0, 0, 3));
  Light light;
  light.matrix[3] = glm::dvec4(0, 4, 6, 1);
  EXPECT_DOUBLE_EQ(referenceDistance(light.position(), p), 5.0);
  EXPECT_EQ(describeReferencePoint(p),
            "the point the camera looks at, on the first object its forward ray meets, (0 0 3)");
}

TEST(GltfReferencePoint, FallsBackToTheObjectsThenThePlanesThenTheEye) {
  // The camera looks away from everything: the centre of the bounded
  // objects' box, planes left out (they have no centre).
  Scene s = sceneLooking({0, 0, 10}, {0, 0, 20});
  s.objects = {object(ObjectKind::Sphere, placed({-4, 0, 0})),
               object(ObjectKind::Cube, placed({4, 2, 0})),
               object(ObjectKind::Plane, placed({0, -100, 0}))};
  ReferencePoint centre = referencePoint(s);
  EXPECT_EQ(centre.source, ReferencePoint::Source::ObjectsCentre);
  EXPECT_EQ(centre.point, glm::dvec3(0, 1, 0));
  // Planes alone, which the ray misses: the nearest plane's point under the
  // eye.
  s.objects = {object(ObjectKind::Plane, placed({0, -1, 0})),
               object(ObjectKind::Plane, placed({7, -3, 1}))};
  ReferencePoint plane = referencePoint(s);
  EXPECT_EQ(plane.source, ReferencePoint::Source::NearestPlane);
  EXPECT_EQ(plane.point, glm::dvec3(0, -1, 10));
  // A plane the ray meets is met like any object.
  Scene floor = sceneLooking({0, 1, 0}, {0, 0, -1});
  floor.objects = {object(ObjectKind::Plane, placed({0, 0, 0}))};
  EXPECT_EQ(referencePoint(floor).source, ReferencePoint::Source::CameraRay);
  EXPECT_NEAR(referencePoint(floor).point.z, -1.0, 1e-15);
  // Nothing at all: the eye.
  s.objects.clear();
  ReferencePoint eye = referencePoint(s);
  EXPECT_EQ(eye.source, ReferencePoint::Source::Eye);
  EXPECT_EQ(eye.point, glm::dvec3(0, 0, 10));
}

TEST(GltfReferencePoint, DistanceIsAlwaysPositiveAndFinite) {
  ReferencePoint origin;
  EXPECT_EQ(referenceDistance(glm::dvec3(0.0), origin), 1.0);
  EXPECT_DOUBLE_EQ(referenceDistance(glm::dvec3(3, 4, 0), origin), 5.0);
  constexpr double kLargest = std::numeric_limits<double>::max();
  ReferencePoint far{glm::dvec3(-kLargest, 0, 0), ReferencePoint::Source::Eye};
  EXPECT_EQ(referenceDistance(glm::dvec3(kLargest, 0, 0), far), kLargest);
  EXPECT_GT(referenceDistance(glm::dvec3(1e-300, 0, 0), origin), 0.0);
  // A camera ray from the largest double finds no finite hit but still a point.
  Scene s;
  s.camera.matrix[3] = glm::dvec4(kLargest, 0, 0, 1);
  s.objects = {object(ObjectKind::Sphere, placed({0, 0, 0}))};
  ReferencePoint p = referencePoint(s);
  EXPECT_EQ(p.source, ReferencePoint::Source::ObjectsCentre);
  EXPECT_EQ(p.point, glm::dvec3(0.0));
}

}  // namespace
}  // namespace scene::gltf
