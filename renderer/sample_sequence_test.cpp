#include "renderer/sample_sequence.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace render {
namespace {

// Whether points [first, first + 2^m) of `sequence` put one point in each
// elementary interval of area 2^-m: for every split m = a + b, each cell
// of 2^a columns by 2^b rows holds one.
::testing::AssertionResult isNet(const PixelSampleSequence& sequence, std::uint32_t first, int m) {
  std::uint32_t count = 1u << m;
  for (int a = 0; a <= m; ++a) {
    int b = m - a;
    std::vector<int> hits(count, 0);
    for (std::uint32_t k = first; k < first + count; ++k) {
      glm::dvec2 p = sequence[k];
      auto column = static_cast<std::uint32_t>(p.x * (1u << a));
      auto row = static_cast<std::uint32_t>(p.y * (1u << b));
      if (++hits[(row << a) | column] > 1) {
        return ::testing::AssertionFailure()
               << "points " << first << " to " << first + count - 1 << ": two in the cell ("
               << column << ", " << row << ") of " << (1u << a) << " x " << (1u << b);
      }
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(SampleSequence, EveryPowerOfTwoPrefixIsStratifiedInEveryElementaryInterval) {
  for (auto [i, j, seed] : {std::tuple{0, 0, 0ull}, std::tuple{17, 3, 0ull},
                            std::tuple{1279, 719, 42ull}, std::tuple{-5, 8, ~0ull}}) {
    PixelSampleSequence sequence(i, j, seed);
    for (int m = 0; m <= 10; ++m) {
      EXPECT_TRUE(isNet(sequence, 0, m)) << "pixel " << i << ", " << j << ", m " << m;
    }
    // And each later block of 2^m points, which the next prefix adds.
    for (int m = 1; m <= 6; ++m) {
      EXPECT_TRUE(isNet(sequence, 1u << m, m)) << "pixel " << i << ", " << j << ", m " << m;
    }
  }
}

TEST(SampleSequence, PointsLieInTheUnitSquare) {
  PixelSampleSequence sequence(3, 4, 5);
  for (std::uint32_t k : {0u, 1u, 2u, 1000u, 65535u, 0xFFFFFFFFu}) {
    glm::dvec2 p = sequence[k];
    EXPECT_GE(p.x, 0.0);
    EXPECT_LT(p.x, 1.0);
    EXPECT_GE(p.y, 0.0);
    EXPECT_LT(p.y, 1.0);
  }
}

TEST(SampleSequence, ThePixelAndTheSeedAloneChooseThePoints) {
  PixelSampleSequence a(10, 20, 7), again(10, 20, 7);
  for (std::uint32_t k = 0; k < 64; ++k) EXPECT_EQ(a[k], again[k]);
  // Another pixel, or another seed, scrambles otherwise.
  for (const PixelSampleSequence& other :
       {PixelSampleSequence(11, 20, 7), PixelSampleSequence(10, 21, 7),
        PixelSampleSequence(10, 20, 8), PixelSampleSequence(20, 10, 7)}) {
    int same = 0;
    for (std::uint32_t k = 0; k < 16; ++k) same += a[k] == other[k] ? 1 : 0;
    EXPECT_EQ(same, 0);
  }
}

TEST(SampleSequence, ScramblingPermutesTheFractions) {
  // An Owen scrambling is a bijection: 2^12 distinct fractions (the top 12
  // bits) map to 2^12 distinct ones.
  std::set<std::uint32_t> seen;
  for (std::uint32_t v = 0; v < 4096; ++v) seen.insert(owenScramble(v << 20, 0x9e3779b9u) >> 20);
  EXPECT_EQ(seen.size(), 4096u);
  // Sobol's first dimension is the van der Corput sequence.
  EXPECT_EQ(sobolFirst(1), 0x80000000u);
  EXPECT_EQ(sobolFirst(3), 0xC0000000u);
  EXPECT_EQ(sobolSecond(1), 0x80000000u);
  EXPECT_EQ(sobolSecond(2), 0xC0000000u);
  EXPECT_EQ(sobolSecond(3), 0x40000000u);
}

}  // namespace
}  // namespace render
