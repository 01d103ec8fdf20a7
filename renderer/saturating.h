// Byte counts that saturate: a hostile size (a count near 2^64, a huge
// image) must give a huge estimate, which is refused, never a wrapped small
// one, which would be allowed.
#pragma once

#include <cstdint>

namespace render {

/// a * b, or UINT64_MAX where that does not fit.
constexpr std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}

/// a + b, or UINT64_MAX where that does not fit.
constexpr std::uint64_t saturatingSum(std::uint64_t a, std::uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

}  // namespace render
