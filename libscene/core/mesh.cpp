#include "scenefile/mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <limits>
#include <numbers>

namespace scene {

namespace {

void addTriangle(TriangleMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

std::uint32_t addVertex(TriangleMesh& mesh, glm::dvec3 position, glm::dvec3 normal) {
  mesh.positions.emplace_back(position);
  mesh.normals.emplace_back(glm::normalize(normal));
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

int clampSegments(int segments) {
  return std::clamp(segments, kMinSegments, kMaxSegments);
}

// The point at angle `phi` on the unit circle of the XZ plane, turning from
// +X toward -Z (counter-clockwise seen from +Y). Exact at quarter turns, so
// that the meshes' extremes are exactly +-1.
glm::dvec2 circlePoint(int step, int steps) {
  if (step % steps == 0) return {1.0, 0.0};
  if (4 * step == steps) return {0.0, -1.0};
  if (2 * step == steps) return {-1.0, 0.0};
  if (4 * step == 3 * steps) return {0.0, 1.0};
  double phi = 2.0 * std::numbers::pi * step / steps;
  return {std::cos(phi), -std::sin(phi)};
}

}  // namespace

TriangleMesh sphereMesh(int segments) {
  segments = clampSegments(segments);
  int rings = std::max(2, segments / 2);
  TriangleMesh mesh;
  std::uint32_t top = addVertex(mesh, {0, 1, 0}, {0, 1, 0});
  // Rings 1 .. rings-1 from the top down, `segments` vertices each.
  for (int r = 1; r < rings; ++r) {
    double theta = std::numbers::pi * r / rings;
    double y = 2 * r == rings ? 0.0 : std::cos(theta);
    double radius = 2 * r == rings ? 1.0 : std::sin(theta);
    for (int s = 0; s < segments; ++s) {
      glm::dvec2 c = circlePoint(s, segments);
      glm::dvec3 p(radius * c.x, y, radius * c.y);
      addVertex(mesh, p, p);
    }
  }
  std::uint32_t bottom = addVertex(mesh, {0, -1, 0}, {0, -1, 0});
  auto ring = [segments](int r, int s) {
    return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments));
  };
  for (int s = 0; s < segments; ++s) addTriangle(mesh, top, ring(1, s), ring(1, s + 1));
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      addTriangle(mesh, ring(r, s), ring(r + 1, s), ring(r + 1, s + 1));
      addTriangle(mesh, ring(r, s), ring(r + 1, s + 1), ring(r, s + 1));
    }
  }
  for (int s = 0; s < segments; ++s) {
    addTriangle(mesh, bottom, ring(rings - 1, s + 1), ring(rings - 1, s));
  }
  return mesh;
}

TriangleMesh cubeMesh() {
  TriangleMesh mesh;
  // Each face: its normal axis and sign; the other two axes run u x v = n.
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      glm::dvec3 n(0.0);
      n[axis] = sign;
      glm::dvec3 u(0.0);
      u[(axis + 1) % 3] = 1.0;
      glm::dvec3 v = glm::cross(n, u);
      std::uint32_t first = static_cast<std::uint32_t>(mesh.positions.size());
      for (auto [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        addVertex(mesh, n + a * u + b * v, n);
      }
      addTriangle(mesh, first, first + 1, first + 2);
      addTriangle(mesh, first, first + 2, first + 3);
    }
  }
  return mesh;
}

TriangleMesh cylinderMesh(int segments) {
  segments = clampSegments(segments);
  TriangleMesh mesh;
  auto step = [segments](int s) { return static_cast<std::uint32_t>(s % segments); };
  // The side: a bottom and a top vertex per step.
  for (int s = 0; s < segments; ++s) {
    glm::dvec2 c = circlePoint(s, segments);
    addVertex(mesh, {c.x, -1, c.y}, {c.x, 0, c.y});
    addVertex(mesh, {c.x, 1, c.y}, {c.x, 0, c.y});
  }
  for (int s = 0; s < segments; ++s) {
    std::uint32_t b0 = 2 * step(s), t0 = b0 + 1, b1 = 2 * step(s + 1), t1 = b1 + 1;
    addTriangle(mesh, b0, b1, t1);
    addTriangle(mesh, b0, t1, t0);
  }
  // The caps: a centre and a ring each.
  for (double y : {1.0, -1.0}) {
    std::uint32_t centre = addVertex(mesh, {0, y, 0}, {0, y, 0});
    for (int s = 0; s < segments; ++s) {
      glm::dvec2 c = circlePoint(s, segments);
      addVertex(mesh, {c.x, y, c.y}, {0, y, 0});
    }
    for (int s = 0; s < segments; ++s) {
      std::uint32_t a = centre + 1 + step(s), b = centre + 1 + step(s + 1);
      if (y > 0) {
        addTriangle(mesh, centre, a, b);
      } else {
        addTriangle(mesh, centre, b, a);
      }
    }
  }
  return mesh;
}

TriangleMesh planeMesh(float halfSize) {
  TriangleMesh mesh;
  double h = halfSize;
  for (auto [x, z] : {std::pair{-h, h}, {h, h}, {h, -h}, {-h, -h}}) {
    addVertex(mesh, {x, 0, z}, {0, 1, 0});
  }
  addTriangle(mesh, 0, 1, 2);
  addTriangle(mesh, 0, 2, 3);
  return mesh;
}

TriangleMesh primitiveMesh(ObjectKind kind, int segments, float planeHalfSize) {
  switch (kind) {
    case ObjectKind::Plane:
      return planeMesh(planeHalfSize);
    case ObjectKind::Sphere:
      return sphereMesh(segments);
    case ObjectKind::Cylinder:
      return cylinderMesh(segments);
    case ObjectKind::Cube:
      return cubeMesh();
  }
  return cubeMesh();
}

namespace {

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void add(const glm::dvec3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

// Everything the scene holds but its planes: the camera's eye, the lights,
// the corners of each object's box, and each plane's origin.
Bounds sceneBounds(const Scene& scene) {
  Bounds b;
  b.add(glm::dvec3(scene.camera.matrix[3]));
  for (const Light& light : scene.lights) b.add(light.position());
  for (const Object& object : scene.objects) {
    if (object.kind == ObjectKind::Plane) {
      b.add(glm::dvec3(object.matrix[3]));
      continue;
    }
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec4 p((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0,
                   1.0);
      b.add(glm::dvec3(object.matrix * p));
    }
  }
  return b;
}

}  // namespace

float scenePlaneHalfSize(const Scene& scene) {
  Bounds b = sceneBounds(scene);
  double reach = 1.0;
  for (const Object& object : scene.objects) {
    if (object.kind != ObjectKind::Plane || b.empty()) continue;
    glm::dmat4 inverse = glm::inverse(object.matrix);
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec4 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                   (corner & 4) ? b.hi.z : b.lo.z, 1.0);
      glm::dvec4 local = inverse * p;
      double r = std::max(std::abs(local.x), std::abs(local.z));
      if (std::isfinite(r)) reach = std::max(reach, r);
    }
  }
  constexpr double kLargest = 1e30;
  double size = std::exp2(std::ceil(std::log2(2.0 * reach)));
  if (!std::isfinite(size) || size > kLargest) size = kLargest;
  return static_cast<float>(size);
}

}  // namespace scene
