#include "libscene/core/default_camera.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

#include "scenefile/transform.h"

namespace scene {

std::optional<glm::dmat4> cameraSeeingObjects(std::span<const Object> objects) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const Object& o : objects) {
    glm::dvec3 p(o.matrix[3]);
    if (std::isfinite(p.x + p.y + p.z)) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  glm::dvec3 centre = lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  double radius = lo.x <= hi.x ? glm::length(hi - lo) / 2 : 0.0;
  glm::dvec3 eye = centre + glm::dvec3(0.0, 0.0, 2.0 * radius + 5.0);
  if (!std::isfinite(eye.x + eye.y + eye.z + radius)) return std::nullopt;
  return cameraFromLookAt(eye, centre);
}

}  // namespace scene
