#include "scenefile/mesh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace scene {
namespace {

// Every triangle faces away from `inside` (or along +Y for the plane), every
// normal is unit length, every index is in range.
void expectWellFormed(const TriangleMesh& mesh, bool flat) {
  ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) ASSERT_LT(mesh.indices[t + k], mesh.positions.size());
    glm::dvec3 a(mesh.positions[mesh.indices[t]]);
    glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
    glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
    glm::dvec3 normal = glm::cross(b - a, c - a);
    ASSERT_GT(glm::length(normal), 0.0) << "degenerate triangle " << t / 3;
    glm::dvec3 out = flat ? glm::dvec3(0, 1, 0) : (a + b + c) / 3.0;
    EXPECT_GT(glm::dot(normal, out), 0.0) << "triangle " << t / 3 << " faces inward";
  }
}

TEST(Mesh, SphereIsAClosedUvSphereOfRadiusOne) {
  for (int segments : {3, 4, 7, 32, 100}) {
    TriangleMesh mesh = sphereMesh(segments);
    expectWellFormed(mesh, false);
    int rings = std::max(2, segments / 2);
    EXPECT_EQ(mesh.positions.size(), static_cast<std::size_t>(2 + (rings - 1) * segments));
    EXPECT_EQ(mesh.indices.size(), static_cast<std::size_t>(3 * 2 * segments * (rings - 1)));
    for (const glm::vec3& p : mesh.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
  }
  // The extremes are exactly +-1 on every axis when the steps allow it.
  TriangleMesh mesh = sphereMesh(32);
  glm::vec3 lo(0.0f), hi(0.0f);
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_EQ(lo, glm::vec3(-1.0f));
  EXPECT_EQ(hi, glm::vec3(1.0f));
}

TEST(Mesh, CubeHasFlatNormalsOnTwentyFourVertices) {
  TriangleMesh mesh = cubeMesh();
  expectWellFormed(mesh, false);
  EXPECT_EQ(mesh.positions.size(), 24u);
  EXPECT_EQ(mesh.indices.size(), 36u);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    // The normal is the axis on which the vertex lies at +-1 for its face.
    glm::vec3 n = mesh.normals[i];
    EXPECT_EQ(glm::dot(n, mesh.positions[i]), 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::abs(mesh.positions[i][k]), 1.0f);
  }
}

TEST(Mesh, CylinderIsCappedFromMinusOneToOne) {
  for (int segments : {3, 8, 32}) {
    TriangleMesh mesh = cylinderMesh(segments);
    expectWellFormed(mesh, false);
    EXPECT_EQ(mesh.positions.size(), static_cast<std::size_t>(4 * segments + 2));
    for (const glm::vec3& p : mesh.positions) {
      EXPECT_EQ(std::abs(p.y), 1.0f);
      float r = std::hypot(p.x, p.z);
      EXPECT_TRUE(r == 0.0f || std::abs(r - 1.0f) < 1e-6f) << r;
    }
  }
}

TEST(Mesh, PlaneIsASquareFacingUp) {
  TriangleMesh mesh = planeMesh(8.0f);
  expectWellFormed(mesh, true);
  EXPECT_EQ(mesh.positions.size(), 4u);
  for (const glm::vec3& p : mesh.positions) {
    EXPECT_EQ(p.y, 0.0f);
    EXPECT_EQ(std::abs(p.x), 8.0f);
    EXPECT_EQ(std::abs(p.z), 8.0f);
  }
}

TEST(Mesh, TessellationIsClamped) {
  EXPECT_EQ(sphereMesh(1).positions.size(), sphereMesh(kMinSegments).positions.size());
  EXPECT_EQ(cylinderMesh(1 << 20).positions.size(), cylinderMesh(kMaxSegments).positions.size());
  EXPECT_EQ(primitiveMesh(ObjectKind::Cube, 5, 1.0f).positions.size(), 24u);
}

}  // namespace
}  // namespace scene
