#include "renderer/float_error.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace render {
namespace {

// nextUp and nextDown step the bits themselves; they must give exactly what
// std::nextafter gives, sign of zero included, or ray origins would move.
TEST(NextFloat, MatchesNextafterBitForBit) {
  using Limits = std::numeric_limits<double>;
  std::vector<double> values = {0.0,
                                -0.0,
                                Limits::denorm_min(),
                                -Limits::denorm_min(),
                                Limits::min(),
                                -Limits::min(),
                                1.0,
                                -1.0,
                                0.1,
                                -0.1,
                                1e300,
                                -1e300,
                                Limits::max(),
                                -Limits::max(),
                                Limits::infinity(),
                                -Limits::infinity()};
  for (double v : values) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(nextUp(v)),
              std::bit_cast<std::uint64_t>(std::nextafter(v, Limits::infinity())))
        << v;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(nextDown(v)),
              std::bit_cast<std::uint64_t>(std::nextafter(v, -Limits::infinity())))
        << v;
  }
  EXPECT_TRUE(std::isnan(nextUp(Limits::quiet_NaN())));
  EXPECT_TRUE(std::isnan(nextDown(Limits::quiet_NaN())));
}

}  // namespace
}  // namespace render
