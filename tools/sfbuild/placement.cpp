#include "tools/sfbuild/placement.h"

#include <cmath>
#include <limits>

#include "scenefile/matrix.h"

namespace sfbuild {
namespace {

// How far the unit shape reaches from its centre along the world axis whose
// row of the linear part is `a`: the largest a . p over the shape's points p.
double reach(scene::ObjectKind kind, const glm::dvec3& a) {
  switch (kind) {
    case scene::ObjectKind::Sphere:
      return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    case scene::ObjectKind::Cube:
      return std::abs(a.x) + std::abs(a.y) + std::abs(a.z);
    case scene::ObjectKind::Cylinder:
      // A disc of radius 1 in x-z at each y in [-1, 1].
      return std::abs(a.y) + std::hypot(a.x, a.z);
    case scene::ObjectKind::Plane:
      break;
  }
  return a.x == 0.0 && a.z == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

glm::dvec3 row(const glm::dmat4& m, int r) {
  return {m[0][r], m[1][r], m[2][r]};
}

glm::dvec3 rounded(const glm::dvec3& p) {
  glm::dvec3 r;
  for (int k = 0; k < 3; ++k) r[k] = std::round(p[k] / kPlacementStep) * kPlacementStep;
  return r;
}

}  // namespace

std::optional<Bounds> objectBounds(scene::ObjectKind kind, const glm::dmat4& matrix) {
  if (kind == scene::ObjectKind::Plane) return {};
  Bounds b;
  for (int axis = 0; axis < 3; ++axis) {
    double r = reach(kind, row(matrix, axis));
    b.low[axis] = matrix[3][axis] - r;
    b.high[axis] = matrix[3][axis] + r;
  }
  return b;
}

double lowestY(scene::ObjectKind kind, const glm::dmat4& matrix) {
  return matrix[3][1] - reach(kind, row(matrix, 1));
}

glm::dvec3 placementPoint(const scene::Camera& camera) {
  glm::dvec3 eye(camera.matrix[3]);
  glm::dvec3 forward = scene::unitDirection(-glm::dvec3(camera.matrix[2]));
  if (forward.y != 0.0) {
    double t = -eye.y / forward.y;
    if (t > 0.0 && t <= kMaxGroundDistance) {
      glm::dvec3 p = eye + t * forward;
      return rounded({p.x, 0.0, p.z});
    }
  }
  return rounded(eye + kPlacementDistance * forward);
}

glm::dmat4 placedObjectMatrix(scene::ObjectKind kind, const scene::Camera& camera) {
  glm::dmat4 m(1.0);
  if (kind == scene::ObjectKind::Plane) return m;
  glm::dvec3 p = placementPoint(camera);
  m[3] = glm::dvec4(p.x, 0.0, p.z, 1.0);
  m[3][1] = -lowestY(kind, m);
  return m;
}

glm::dvec3 placedLightPosition(const scene::Scene& scene) {
  std::optional<Bounds> all;
  for (const scene::Object& object : scene.objects) {
    std::optional<Bounds> b = objectBounds(object.kind, object.matrix);
    if (!b || !std::isfinite(b->low.x + b->low.y + b->low.z + b->high.x + b->high.y + b->high.z))
      continue;
    if (!all) {
      all = b;
    } else {
      all->low = glm::min(all->low, b->low);
      all->high = glm::max(all->high, b->high);
    }
  }
  if (!all) return placementPoint(scene.camera) + glm::dvec3(0.0, kLightHeightAboveScene, 0.0);
  glm::dvec3 middle = (all->low + all->high) * 0.5;
  return {middle.x, all->high.y + kLightHeightAboveScene, middle.z};
}

}  // namespace sfbuild
