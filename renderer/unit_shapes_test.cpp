#include "renderer/unit_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace render {
namespace {

using scene::ObjectKind;

TEST(UnitShapes, SphereSpanThroughTheCentre) {
  ShapeSpan s = intersectUnitShape(ObjectKind::Sphere, {0, 0, 5}, {0, 0, -1});
  ASSERT_FALSE(s.empty);
  EXPECT_EQ(s.enter, 4.0);
  EXPECT_EQ(s.exit, 6.0);
  EXPECT_EQ(s.enterNormal, glm::dvec3(0, 0, 1));
}

TEST(UnitShapes, SmallSphereFarAwayKeepsItsDigits) {
  // The sphere seen from 1e9 radii: the naive discriminant b^2 - ac loses
  // all its digits there; the hit must still be within rounding of exact.
  for (double offset : {0.0, 0.5, 0.999999}) {
    ShapeSpan s = intersectUnitShape(ObjectKind::Sphere, {offset, 0, 1e9}, {0, 0, -1});
    ASSERT_FALSE(s.empty) << offset;
    double exact = 1e9 - std::sqrt(1.0 - offset * offset);
    EXPECT_NEAR(s.enter, exact, 1e9 * 4e-16) << offset;
  }
  EXPECT_TRUE(intersectUnitShape(ObjectKind::Sphere, {1.000001, 0, 1e9}, {0, 0, -1}).empty);
}

TEST(UnitShapes, HugeSphereCloseBy) {
  // Seen from just outside, in units of a radius of 1e4 at 1e-3 away.
  ShapeSpan s = intersectUnitShape(ObjectKind::Sphere, {0, 0, 1.0 + 1e-7}, {0, 0, -1});
  ASSERT_FALSE(s.empty);
  EXPECT_NEAR(s.enter, 1e-7, 1e-16);
}

TEST(UnitShapes, AxisParallelRaysWithNegativeZeroThroughCubeFacesEdgesCorners) {
  // Every combination of origins on faces, edges and corners, directions
  // along an axis with the other components +0 or -0: a hit, never NaN.
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      for (double a : {-1.0, -0.5, -0.0, 0.0, 0.5, 1.0}) {
        for (double b : {-1.0, -0.0, 0.0, 1.0}) {
          glm::dvec3 d(-0.0, -0.0, -0.0);
          d[axis] = -sign;
          glm::dvec3 o(0.0);
          o[axis] = 5.0 * sign;
          o[(axis + 1) % 3] = a;
          o[(axis + 2) % 3] = b;
          ShapeSpan s = intersectUnitShape(ObjectKind::Cube, o, d);
          ASSERT_FALSE(s.empty) << axis << " " << a << " " << b;
          EXPECT_EQ(s.enter, 4.0);
          EXPECT_EQ(s.exit, 6.0);
          EXPECT_FALSE(std::isnan(s.enterNormal.x + s.enterNormal.y + s.enterNormal.z));
          EXPECT_EQ(s.enterNormal[axis], sign);
        }
      }
    }
  }
}

TEST(UnitShapes, DiagonalRaysThroughEdgesAndCornersDoNotLeak) {
  // Rays aimed exactly at an edge or a corner of the cube hit it: no
  // background shows through where two faces meet.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    glm::dvec3 target(i % 2 ? 1.0 : -1.0, (i / 2) % 2 ? 1.0 : -1.0, u(rng));  // on an edge
    if (i % 3 == 0) target.z = (i / 4) % 2 ? 1.0 : -1.0;                      // a corner
    glm::dvec3 origin(u(rng) * 10, u(rng) * 10, u(rng) * 10);
    if (std::abs(origin.x) <= 1 && std::abs(origin.y) <= 1 && std::abs(origin.z) <= 1) continue;
    ShapeSpan s = intersectUnitShape(ObjectKind::Cube, origin, target - origin);
    ASSERT_FALSE(s.empty) << i;
    ASSERT_TRUE(std::isfinite(s.enter) && std::isfinite(s.exit));
    // The target, at t = 1, lies in the span (up to rounding).
    ASSERT_LE(s.enter, 1.0 + 1e-12) << i;
    ASSERT_GE(s.exit, 1.0 - 1e-12) << i;
  }
}

TEST(UnitShapes, RayAlongTheCylinderAxis) {
  ShapeSpan s = intersectUnitShape(ObjectKind::Cylinder, {0.3, 5, -0.2}, {-0.0, -1, 0.0});
  ASSERT_FALSE(s.empty);
  EXPECT_EQ(s.enter, 4.0);
  EXPECT_EQ(s.exit, 6.0);
  EXPECT_EQ(s.enterNormal, glm::dvec3(0, 1, 0));
  EXPECT_TRUE(intersectUnitShape(ObjectKind::Cylinder, {1.5, 5, 0}, {0, -1, 0}).empty);
  // On the rim itself.
  EXPECT_FALSE(intersectUnitShape(ObjectKind::Cylinder, {1.0, 5, 0}, {0, -1, 0}).empty);
}

TEST(UnitShapes, CylinderRimsAndSeamAreWatertight) {
  // Rays aimed at the rim circles from all around hit, from side or cap.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    double angle = u(rng) * 3.141592653589793;
    glm::dvec3 rim(std::cos(angle), i % 2 ? 1.0 : -1.0, std::sin(angle));
    glm::dvec3 origin(u(rng) * 10, u(rng) * 10, u(rng) * 10);
    if (origin.x * origin.x + origin.z * origin.z <= 1.0 && std::abs(origin.y) <= 1.0) continue;
    ShapeSpan s = intersectUnitShape(ObjectKind::Cylinder, origin, rim - origin);
    // The rim point lies on the surface up to the rounding of cos and sin.
    if (s.empty) {
      glm::dvec3 nudged = rim * (1.0 - 1e-12);
      nudged.y = rim.y * (1.0 - 1e-12);
      ASSERT_FALSE(intersectUnitShape(ObjectKind::Cylinder, origin, nudged - origin).empty) << i;
    } else {
      ASSERT_LE(s.enter, 1.0 + 1e-9);
    }
  }
}

TEST(UnitShapes, PlaneFromBothSidesAndParallel) {
  ShapeSpan above = intersectUnitShape(ObjectKind::Plane, {0, 2, 0}, {0, -1, 0});
  EXPECT_EQ(above.enter, 2.0);
  ShapeSpan below = intersectUnitShape(ObjectKind::Plane, {0, -2, 0}, {0, 0.5, 0});
  EXPECT_EQ(below.enter, 4.0);
  EXPECT_TRUE(intersectUnitShape(ObjectKind::Plane, {0, 1, 0}, {1, 0, -0.0}).empty);
  EXPECT_TRUE(intersectUnitShape(ObjectKind::Plane, {0, 0, 0}, {1, 0, 0}).empty);
}

TEST(UnitShapes, GrazingRaysGiveFiniteResults) {
  for (double y : {1.0, std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)}) {
    for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder}) {
      ShapeSpan s = intersectUnitShape(kind, {-5, y, 0}, {1, 0, 0});
      if (!s.empty) {
        EXPECT_TRUE(std::isfinite(s.enter) && std::isfinite(s.exit));
        EXPECT_LE(s.enter, s.exit);
      }
    }
  }
}

TEST(UnitShapes, RefinedPointsLieOnTheSurface) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    glm::dvec3 o(u(rng) * 100, u(rng) * 100, u(rng) * 100);
    glm::dvec3 d = glm::dvec3(u(rng), u(rng), u(rng)) - o / 100.0;
    for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Cube, ObjectKind::Cylinder}) {
      ShapeSpan s = intersectUnitShape(kind, o, d);
      if (s.empty || s.enter <= 0) continue;
      SurfacePoint p = refineOntoSurface(kind, o, d, s.enter, s.enterNormal);
      switch (kind) {
        case ObjectKind::Sphere:
          ASSERT_NEAR(glm::length(p.point), 1.0, 4e-16);
          break;
        case ObjectKind::Cube:
          ASSERT_EQ(std::max({std::abs(p.point.x), std::abs(p.point.y), std::abs(p.point.z)}), 1.0);
          break;
        default:
          ASSERT_TRUE(std::abs(std::abs(p.point.y) - 1.0) == 0.0 ||
                      std::abs(std::hypot(p.point.x, p.point.z) - 1.0) < 4e-16);
      }
      // From outside, the ray enters against the outward normal.
      EXPECT_LE(glm::dot(p.normal, d), 0.0);
    }
  }
}

}  // namespace
}  // namespace render
