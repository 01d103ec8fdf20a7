// Floating-point error bounds, after pbrt-v4's gamma(n) and next-float steps:
// the tools for placing a new ray's origin just off a surface by exactly as
// much as the hit point may be wrong, at any scale.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace render {

inline constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon() * 0.5;

// Bound on the relative error of n successive roundings: n u / (1 - n u).
constexpr double gamma(int n) {
  return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon);
}

// std::nextafter(v, +infinity) and (v, -infinity), by stepping the bits as
// glibc does, inline: nextafter is a library call, made for every new ray's
// origin. The same results: zero steps to the smallest subnormal of the
// direction's sign, NaN stays, an infinity in the direction stays, and any
// other value moves one step (a negative one by one bit down in magnitude,
// so -denorm_min goes to -0, and -infinity to -max).
inline double nextUp(double v) {
  if (v != v || v == std::numeric_limits<double>::infinity()) return v;
  if (v == 0.0) return std::numeric_limits<double>::denorm_min();
  auto bits = std::bit_cast<std::uint64_t>(v);
  bits = v > 0.0 ? bits + 1 : bits - 1;
  return std::bit_cast<double>(bits);
}
inline double nextDown(double v) {
  if (v != v || v == -std::numeric_limits<double>::infinity()) return v;
  if (v == 0.0) return -std::numeric_limits<double>::denorm_min();
  auto bits = std::bit_cast<std::uint64_t>(v);
  bits = v < 0.0 ? bits + 1 : bits - 1;
  return std::bit_cast<double>(bits);
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
