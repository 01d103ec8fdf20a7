#include "renderer/sample_sequence.h"

namespace render {

namespace {

std::uint32_t reverseBits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
  v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
  return (v >> 16) | (v << 16);
}

// SplitMix64's finaliser: the pixel's and the seed's bits spread over the
// scrambling seeds.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

std::uint32_t sobolFirst(std::uint32_t index) {
  return reverseBits(index);
}

std::uint32_t sobolSecond(std::uint32_t index) {
  // The second dimension's generator matrix is Pascal's triangle mod 2: its
  // column k is the previous one xor itself shifted by one.
  std::uint32_t result = 0;
  for (std::uint32_t column = 1u << 31; index != 0; index >>= 1, column ^= column >> 1) {
    if (index & 1u) result ^= column;
  }
  return result;
}

std::uint32_t owenScramble(std::uint32_t v, std::uint32_t seed) {
  // The hash works on the reversed bits: each output bit then depends on
  // its own bit and the more significant ones of the fraction, as an Owen
  // scrambling's permutations do.
  v = reverseBits(v);
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return reverseBits(v);
}

PixelSampleSequence::PixelSampleSequence(int i, int j, std::uint64_t seed) {
  std::uint64_t state =
      mix(seed ^ mix((static_cast<std::uint64_t>(static_cast<std::uint32_t>(j)) << 32) ^
                     static_cast<std::uint32_t>(i)));
  xSeed_ = static_cast<std::uint32_t>(mix(state) >> 32);
  ySeed_ = static_cast<std::uint32_t>(mix(state + 1) >> 32);
}

glm::dvec2 PixelSampleSequence::operator[](std::uint32_t index) const {
  constexpr double kFraction = 0x1.0p-32;
  return {owenScramble(sobolFirst(index), xSeed_) * kFraction,
          owenScramble(sobolSecond(index), ySeed_) * kFraction};
}

}  // namespace render
