#include "tools/sfbuild/placement.h"

#include <cmath>
#include <limits>

#include "scenefile/matrix.h"
#include "scenefile/scene_summary.h"

namespace sfbuild {
namespace {

glm::dvec3 rounded(const glm::dvec3& p) {
  glm::dvec3 r;
  for (int k = 0; k < 3; ++k) r[k] = std::round(p[k] / kPlacementStep) * kPlacementStep;
  return r;
}

}  // namespace

double lowestY(scene::ObjectKind kind, const glm::dmat4& matrix) {
  if (std::optional<scene::Bounds> b = scene::objectBounds(kind, matrix)) return b->low.y;
  // A plane spans its local x and z: level only where neither moves y.
  return matrix[0][1] == 0.0 && matrix[2][1] == 0.0 ? matrix[3][1]
                                                    : -std::numeric_limits<double>::infinity();
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
  std::optional<scene::Bounds> all = scene::summarizeScene(scene).bounds;
  if (!all) return placementPoint(scene.camera) + glm::dvec3(0.0, kLightHeightAboveScene, 0.0);
  glm::dvec3 middle = (all->low + all->high) * 0.5;
  return {middle.x, all->high.y + kLightHeightAboveScene, middle.z};
}

}  // namespace sfbuild
