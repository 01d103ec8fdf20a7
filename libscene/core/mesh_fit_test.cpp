#include "scenefile/mesh_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>
#include <random>
#include <vector>

#include "scenefile/mesh.h"

namespace scene {
namespace {

struct Positions {
  std::vector<glm::dvec3> points;
  std::vector<std::uint32_t> indices;
};

// A mesh of the library's, moved by `m` into the space a file would hold
// it in, rounded to float as a file stores it.
Positions placed(const TriangleMesh& mesh, const glm::dmat4& m) {
  Positions out;
  for (const glm::vec3& p : mesh.positions) {
    glm::dvec3 q(m * glm::dvec4(glm::dvec3(p), 1.0));
    out.points.emplace_back(glm::vec3(q));
  }
  out.indices = mesh.indices;
  return out;
}

double largestDifference(const glm::dmat4& a, const glm::dmat4& b) {
  double d = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  }
  return d;
}

glm::dmat4 shape(const glm::dquat& q, const glm::dvec3& scale, const glm::dvec3& offset) {
  glm::dmat4 m(glm::mat3_cast(q));
  for (int i = 0; i < 3; ++i) m[i] *= scale[i];
  m[3] = glm::dvec4(offset, 1.0);
  return m;
}

TEST(MeshFit, RecognisesEachPrimitiveAtItsPlaceSizeAndRotation) {
  std::mt19937_64 rng(5);
  auto u = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  for (int trial = 0; trial < 40; ++trial) {
    glm::dquat q = glm::normalize(glm::dquat(u(-1, 1), u(-1, 1), u(-1, 1), u(-1, 1)));
    glm::dvec3 offset(u(-5, 5), u(-5, 5), u(-5, 5));
    double r = u(0.2, 3.0);
    // A sphere: rotation cannot be seen, so the fit is the scale alone.
    Positions sphere = placed(sphereMesh(24), shape(q, glm::dvec3(r), offset));
    FitResult s = fitPrimitive(sphere.points, sphere.indices);
    ASSERT_TRUE(s.fit) << s.reason;
    EXPECT_EQ(s.fit->kind, ObjectKind::Sphere);
    EXPECT_LT(largestDifference(s.fit->shape, shape(glm::dquat(1, 0, 0, 0), glm::dvec3(r), offset)),
              1e-5);
    // A box with three different sides: the frame and the sides come back
    // up to the order of the axes, so compare what the shape does.
    glm::dvec3 sides(u(0.2, 3), u(0.2, 3), u(0.2, 3));
    glm::dmat4 boxShape = shape(q, sides, offset);
    Positions box = placed(cubeMesh(), boxShape);
    FitResult b = fitPrimitive(box.points, box.indices);
    ASSERT_TRUE(b.fit) << b.reason;
    EXPECT_EQ(b.fit->kind, ObjectKind::Cube);
    for (const glm::vec3& corner : cubeMesh().positions) {
      glm::dvec3 want(boxShape * glm::dvec4(glm::dvec3(corner), 1.0));
      double nearest = 1e9;
      for (const glm::vec3& c : cubeMesh().positions) {
        nearest = std::min(
            nearest, glm::length(glm::dvec3(b.fit->shape * glm::dvec4(glm::dvec3(c), 1.0)) - want));
      }
      EXPECT_LT(nearest, 1e-5);
    }
    EXPECT_NEAR(std::abs(glm::determinant(glm::dmat3(b.fit->shape))),
                std::abs(glm::determinant(glm::dmat3(boxShape))), 1e-4);
    // A cylinder along any axis.
    glm::dvec3 size(r, u(0.2, 4), r);
    glm::dmat4 cylShape = shape(q, size, offset);
    Positions cyl = placed(cylinderMesh(20), cylShape);
    FitResult c = fitPrimitive(cyl.points, cyl.indices);
    ASSERT_TRUE(c.fit) << c.reason;
    EXPECT_EQ(c.fit->kind, ObjectKind::Cylinder);
    glm::dvec3 axis = glm::normalize(glm::dvec3(cylShape[1]));
    EXPECT_NEAR(std::abs(glm::dot(glm::normalize(glm::dvec3(c.fit->shape[1])), axis)), 1.0, 1e-6);
    EXPECT_NEAR(glm::length(glm::dvec3(c.fit->shape[1])), size.y, 1e-5);
    EXPECT_NEAR(glm::length(glm::dvec3(c.fit->shape[0])), r, 1e-5);
    EXPECT_LT(glm::length(glm::dvec3(c.fit->shape[3]) - offset), 1e-5);
    // A quad.
    Positions quad = placed(planeMesh(1.0f), shape(q, glm::dvec3(2.0), offset));
    FitResult p = fitPrimitive(quad.points, quad.indices);
    ASSERT_TRUE(p.fit) << p.reason;
    EXPECT_EQ(p.fit->kind, ObjectKind::Plane);
    glm::dvec3 normal = glm::mat3_cast(q) * glm::dvec3(0, 1, 0);
    EXPECT_NEAR(glm::dot(glm::normalize(glm::dvec3(p.fit->shape[1])), normal), 1.0, 1e-6);
    EXPECT_LT(glm::length(glm::dvec3(p.fit->shape[3]) - offset), 1e-5);
  }
}

TEST(MeshFit, AnUprightShapeKeepsItsFrame) {
  Positions cyl =
      placed(cylinderMesh(16), shape(glm::dquat(1, 0, 0, 0), {0.5, 1.5, 0.5}, {1, 2, 3}));
  FitResult c = fitPrimitive(cyl.points, cyl.indices);
  ASSERT_TRUE(c.fit);
  glm::dmat4 want(1.0);
  want[0][0] = 0.5;
  want[1][1] = 1.5;
  want[2][2] = 0.5;
  want[3] = glm::dvec4(1, 2, 3, 1);
  EXPECT_LT(largestDifference(c.fit->shape, want), 1e-6);
  EXPECT_EQ(c.fit->shape[0][1], 0.0);  // snapped, not tilted by float rounding
}

TEST(MeshFit, ADiscIsAPlane) {
  TriangleMesh cylinder = cylinderMesh(24);
  // The top cap alone: a centre and its ring.
  Positions disc;
  for (std::size_t i = 2 * 24; i < 2 * 24 + 25; ++i)
    disc.points.emplace_back(cylinder.positions[i]);
  for (std::uint32_t s = 0; s < 24; ++s)
    disc.indices.insert(disc.indices.end(), {0, 1 + s, 1 + (s + 1) % 24});
  FitResult d = fitPrimitive(disc.points, disc.indices);
  ASSERT_TRUE(d.fit) << d.reason;
  EXPECT_EQ(d.fit->kind, ObjectKind::Plane);
  EXPECT_NEAR(d.fit->shape[3][1], 1.0, 1e-9);
}

TEST(MeshFit, RejectsWhatIsNoPrimitive) {
  // A torus.
  Positions torus;
  const int rings = 24, sides = 12;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      double a = 2 * std::numbers::pi * i / rings, b = 2 * std::numbers::pi * j / sides,
             r = 1 + 0.3 * std::cos(b);
      torus.points.emplace_back(r * std::cos(a), 0.3 * std::sin(b), -r * std::sin(a));
      std::uint32_t p = i * sides + j, q = ((i + 1) % rings) * sides + j;
      std::uint32_t p1 = i * sides + (j + 1) % sides,
                    q1 = ((i + 1) % rings) * sides + (j + 1) % sides;
      torus.indices.insert(torus.indices.end(), {p, q, q1, p, q1, p1});
    }
  }
  FitResult t = fitPrimitive(torus.points, torus.indices);
  EXPECT_FALSE(t.fit);
  EXPECT_FALSE(t.reason.empty());
  // Half a sphere: its vertices lie on one sphere, but it is not whole.
  TriangleMesh sphere = sphereMesh(16);
  Positions half;
  for (const glm::vec3& p : sphere.positions) half.points.emplace_back(p);
  for (std::size_t i = 0; i < sphere.indices.size(); i += 3) {
    bool upper = true;
    for (int k = 0; k < 3; ++k) upper &= sphere.positions[sphere.indices[i + k]].y >= 0.0f;
    if (upper)
      half.indices.insert(half.indices.end(), sphere.indices.begin() + i,
                          sphere.indices.begin() + i + 3);
  }
  EXPECT_FALSE(fitPrimitive(half.points, half.indices).fit);
  // A sphere whose vertices wander by 1%.
  Positions bumpy = placed(sphereMesh(16), glm::dmat4(1.0));
  for (std::size_t i = 0; i < bumpy.points.size(); i += 2) bumpy.points[i] *= 1.01;
  EXPECT_FALSE(fitPrimitive(bumpy.points, bumpy.indices).fit);
  // Nothing at all.
  EXPECT_FALSE(fitPrimitive({}, {}).fit);
}

TEST(MeshFit, RefusesTrianglesItCannotRead) {
  // The public API takes anyone's arrays (the Python module's): an index
  // past the vertices, a NaN or a broken triangle is a reason, not a crash.
  Positions cube = placed(cubeMesh(), glm::dmat4(1.0));
  ASSERT_TRUE(fitPrimitive(cube.points, cube.indices).fit);
  std::vector<std::uint32_t> past = cube.indices;
  past[4] = static_cast<std::uint32_t>(cube.points.size());
  FitResult r = fitPrimitive(cube.points, past);
  EXPECT_FALSE(r.fit);
  EXPECT_EQ(r.reason, "index 24 is past the 24 vertices");
  std::vector<glm::dvec3> nan = cube.points;
  nan[3].y = std::nan("");
  r = fitPrimitive(nan, cube.indices);
  EXPECT_FALSE(r.fit);
  EXPECT_EQ(r.reason, "vertex 3 is not finite");
  std::vector<std::uint32_t> broken(cube.indices.begin(), cube.indices.end() - 1);
  r = fitPrimitive(cube.points, broken);
  EXPECT_FALSE(r.fit);
  EXPECT_EQ(r.reason, "35 indices are not whole triangles");
}

}  // namespace
}  // namespace scene
