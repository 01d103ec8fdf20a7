#include "scenefile/srgb.h"

#include <gtest/gtest.h>

namespace scene {
namespace {

TEST(Srgb, CurveHasItsPublishedValuesAndInverts) {
  EXPECT_DOUBLE_EQ(srgbToLinear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgbToLinear(1.0), 1.0);
  EXPECT_NEAR(srgbToLinear(0.5), 0.214041, 1e-6);
  EXPECT_NEAR(linearToSrgb(0.18), 0.461356, 1e-6);
  EXPECT_DOUBLE_EQ(srgbToLinear(0.04), 0.04 / 12.92);
  for (double v : {1e-300, 0.001, 0.04045, 0.2, 0.8, 1.0, 2.5, 1e10}) {
    EXPECT_NEAR(linearToSrgb(srgbToLinear(v)) / v, 1.0, 1e-12) << v;
  }
  // Past 1 the curve goes on, so that a light brighter than 1 stays so.
  EXPECT_GT(srgbToLinear(2.0), 2.0);
}

TEST(Srgb, BelowZeroIsZero) {
  EXPECT_EQ(srgbToLinear(-0.5), 0.0);
  EXPECT_EQ(linearToSrgb(-0.5), 0.0);
}

}  // namespace
}  // namespace scene
