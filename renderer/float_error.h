// Floating-point error bounds, after pbrt-v4's gamma(n) and next-float steps:
// the tools for placing a new ray's origin just off a surface by exactly as
// much as the hit point may be wrong, at any scale.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace render {

inline constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon() * 0.5;

// Bound on the relative error of n successive roundings: n u / (1 - n u).
constexpr double gamma(int n) {
  return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon);
}

inline double nextUp(double v) {
  return std::nextafter(v, std::numeric_limits<double>::infinity());
}
inline double nextDown(double v) {
  return std::nextafter(v, -std::numeric_limits<double>::infinity());
}

inline glm::dvec3 abs(const glm::dvec3& v) {
  return {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
}

// Moves p off the surface with normal n, to the side that w points to, by
// the error bound pError projected on the normal, and rounds away from the
// surface so that the rounding of the addition cannot undo the move.
inline glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& pError,
                                  const glm::dvec3& n, const glm::dvec3& w) {
  double d = glm::dot(abs(n), pError);
  glm::dvec3 offset = d * n;
  if (glm::dot(w, n) < 0.0) offset = -offset;
  glm::dvec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.0) {
      po[i] = nextUp(po[i]);
    } else if (offset[i] < 0.0) {
      po[i] = nextDown(po[i]);
    }
  }
  return po;
}

}  // namespace render
