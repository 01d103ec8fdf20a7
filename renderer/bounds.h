// Axis-aligned boxes for the bounding volume hierarchy.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>

#include "renderer/float_error.h"

namespace render {

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Bounds& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  void extend(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  glm::dvec3 centre() const { return 0.5 * (lo + hi); }
  double surfaceArea() const {
    glm::dvec3 e = hi - lo;
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

// The nearest float at or below a double, and at or above it: float box
// planes rounded outward, so that a float box still contains the double one.
// The step to the next float is std::nextafter's, done on the bits and
// chosen without a branch: a BVH build rounds six planes a node, and which
// way the nearest float lies is a coin toss that a branch mispredicts half
// the time.
inline float floatAtOrBelow(double v) {
  float f = static_cast<float>(v);
  // One step toward -infinity, for f above v (so neither -infinity nor
  // NaN): from either zero to the negative float nearest zero.
  std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  std::uint32_t below = (bits & 0x7FFFFFFFu) == 0 ? 0x80000001u : bits >> 31 ? bits + 1 : bits - 1;
  return static_cast<double>(f) > v ? std::bit_cast<float>(below) : f;
}
inline float floatAtOrAbove(double v) {
  float f = static_cast<float>(v);
  // One step toward +infinity, for f below v (so neither +infinity nor
  // NaN): from either zero to the positive float nearest zero.
  std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  std::uint32_t above = (bits & 0x7FFFFFFFu) == 0 ? 0x00000001u : bits >> 31 ? bits - 1 : bits + 1;
  return static_cast<double>(f) < v ? std::bit_cast<float>(above) : f;
}

// A ray prepared for many box tests.
struct BoxRay {
  glm::dvec3 origin;
  glm::dvec3 inverseDirection;
};

// Whether the ray meets the box for some t in [tMin, tMax]. Conservative:
// the far distances are widened by their rounding error (pbrt-v4), so that
// no hit is lost at a box's edge, and a 0 * infinity NaN (a ray parallel to a
// slab and starting on its plane) is ignored rather than taken as a miss.
inline bool hitsBox(const Bounds& b, const BoxRay& r, double tMin, double tMax) {
  for (int i = 0; i < 3; ++i) {
    double tNear = (b.lo[i] - r.origin[i]) * r.inverseDirection[i];
    double tFar = (b.hi[i] - r.origin[i]) * r.inverseDirection[i];
    if (tNear > tFar) std::swap(tNear, tFar);
    tFar *= 1.0 + 2.0 * gamma(3);
    tMin = tNear > tMin ? tNear : tMin;
    tMax = tFar < tMax ? tFar : tMax;
    if (tMin > tMax) return false;
  }
  return true;
}

}  // namespace render
