// Axis-aligned boxes for the bounding volume hierarchy.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// A box's six planes rounded outward to floats, the low corner's then the
// high one's: floatAtOrBelow of each low plane and floatAtOrAbove of each
// high one, bit for bit. With SSE2 the six go through together, the high
// planes negated (rounding up is rounding the negation down, negated): a
// BVH build rounds a box for each of its nodes, and one plane at a time
// this was a sixth of the build.
inline void floatPlanesAround(const Bounds& box, float planes[6]) {
#if defined(__SSE2__)
  const __m128d negate = _mm_set1_pd(-0.0);
  __m128d v0 = _mm_setr_pd(box.lo.x, box.lo.y);
  __m128d v1 = _mm_setr_pd(box.lo.z, -box.hi.x);
  __m128d v2 = _mm_xor_pd(_mm_setr_pd(box.hi.y, box.hi.z), negate);
  __m128 nearest = _mm_movelh_ps(_mm_cvtpd_ps(v0), _mm_cvtpd_ps(v1));
  __m128 nearestLast = _mm_cvtpd_ps(v2);
  // Where the nearest float lies above the double, one step down; the
  // masks of the 64-bit compares packed to 32-bit lanes.
  __m128 above =
      _mm_shuffle_ps(_mm_castpd_ps(_mm_cmpgt_pd(_mm_cvtps_pd(nearest), v0)),
                     _mm_castpd_ps(_mm_cmpgt_pd(_mm_cvtps_pd(_mm_movehl_ps(nearest, nearest)), v1)),
                     _MM_SHUFFLE(2, 0, 2, 0));
  __m128 aboveLast = _mm_shuffle_ps(_mm_castpd_ps(_mm_cmpgt_pd(_mm_cvtps_pd(nearestLast), v2)),
                                    _mm_setzero_ps(), _MM_SHUFFLE(2, 0, 2, 0));
  auto stepDown = [](__m128 f, __m128 where) {
    // As floatAtOrBelow: bits - 1 for a positive float, bits + 1 for a
    // negative one, and the negative float nearest zero from either zero.
    __m128i bits = _mm_castps_si128(f);
    __m128i sign = _mm_srai_epi32(bits, 31);
    __m128i step = _mm_sub_epi32(_mm_sub_epi32(bits, _mm_set1_epi32(1)), _mm_add_epi32(sign, sign));
    __m128i zero =
        _mm_cmpeq_epi32(_mm_and_si128(bits, _mm_set1_epi32(0x7FFFFFFF)), _mm_setzero_si128());
    step = _mm_or_si128(_mm_and_si128(zero, _mm_set1_epi32(static_cast<int>(0x80000001u))),
                        _mm_andnot_si128(zero, step));
    __m128i w = _mm_castps_si128(where);
    return _mm_castsi128_ps(_mm_or_si128(_mm_and_si128(w, step), _mm_andnot_si128(w, bits)));
  };
  // Lanes 3, and 0 and 1 of the last, were the high planes: negated back.
  __m128 first = _mm_xor_ps(stepDown(nearest, above), _mm_setr_ps(0.0f, 0.0f, 0.0f, -0.0f));
  __m128 last = _mm_xor_ps(stepDown(nearestLast, aboveLast), _mm_set1_ps(-0.0f));
  _mm_storeu_ps(planes, first);
  _mm_storel_pi(reinterpret_cast<__m64*>(planes + 4), last);
#else
  for (int i = 0; i < 3; ++i) {
    planes[i] = floatAtOrBelow(box.lo[i]);
    planes[3 + i] = floatAtOrAbove(box.hi[i]);
  }
#endif
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
  // All three slabs, then one test: the interval only narrows from slab to
  // slab, so leaving early changes no answer, and the branch at each slab,
  // which goes either way as shadow rays meet or miss their cell's boxes,
  // cost more than the slabs it skipped (docs/history/PERFORMANCE.md, "Big
  // scenes: bins, planes and pages").
  for (int i = 0; i < 3; ++i) {
    double tNear = (b.lo[i] - r.origin[i]) * r.inverseDirection[i];
    double tFar = (b.hi[i] - r.origin[i]) * r.inverseDirection[i];
    double lower = tNear > tFar ? tFar : tNear;
    double upper = (tNear > tFar ? tNear : tFar) * (1.0 + 2.0 * gamma(3));
    tMin = lower > tMin ? lower : tMin;
    tMax = upper < tMax ? upper : tMax;
  }
  return !(tMin > tMax);
}

}  // namespace render
