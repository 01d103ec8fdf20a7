// The positions of a pixel's samples: Owen-scrambled Sobol points (Burley
// 2020, "Practical Hash-based Owen Scrambling"). The first two Sobol
// dimensions form a (0,2)-sequence, and Owen scrambling keeps that: every
// power-of-two prefix of 2^m points puts one point in each elementary
// interval of area 2^-m. An edge through the pixel then leaves an error that
// falls as N^-0.75 where jittered cells' falls as N^-0.5.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>

namespace render {

// Sobol's first dimension of point `index`, as a 32-bit fraction.
std::uint32_t sobolFirst(std::uint32_t index);
// Sobol's second dimension of point `index`, as a 32-bit fraction.
std::uint32_t sobolSecond(std::uint32_t index);
// An Owen scrambling of the 32-bit fraction `v`: a random permutation of
// each binary interval's halves, chosen by `seed` (Burley's hash, as
// pbrt-v4's FastOwenScrambler).
std::uint32_t owenScramble(std::uint32_t v, std::uint32_t seed);

// One pixel's sequence of points in [0, 1)^2. Its scrambling is a function
// of the pixel and the scene's seed alone, so a pixel's samples are the same
// whatever thread, tile or region traces them.
class PixelSampleSequence {
 public:
  PixelSampleSequence(int i, int j, std::uint64_t seed);

  // Point `index` of the sequence; every coordinate is a multiple of 2^-32,
  // exact in a double.
  glm::dvec2 operator[](std::uint32_t index) const;

 private:
  std::uint32_t xSeed_, ySeed_;
};

}  // namespace render
