#include "renderer/image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scenefile/srgb.h"

namespace render {
namespace {

// The level by rounding in double: a float plus 0.5 is exact there, and its
// truncation rounds halves up for a value of at least 0.
long levelInDouble(float v, double levels) {
  float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  if (levels == 255.0) return static_cast<long>(static_cast<double>(clamped * 255.0f) + 0.5);
  return static_cast<long>(static_cast<double>(clamped) * levels + 0.5);
}

// Every level's halfway point and its float neighbours, for 8 and 16 bits:
// the render's retracing (levelOf) and the writers (eightBitLevels) agree.
TEST(ImageLevels, LevelOfRoundsHalvesUpAndEightBitLevelsAgree) {
  for (double levels : {255.0, 65535.0}) {
    for (int level = 0; level < static_cast<int>(levels); level += levels == 255.0 ? 1 : 97) {
      float v = static_cast<float>((level + 0.5) / levels);
      for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
      for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) {
        ASSERT_EQ(levelOf(v, levels), levelInDouble(v, levels)) << v << " of " << levels;
        if (levels == 255.0) {
          ASSERT_EQ(eightBitLevel(v), levelOf(v, 255.0)) << v;
        }
      }
    }
  }
  EXPECT_EQ(levelOf(0.5f, 255.0), 128);  // 127.5 rounds up
  EXPECT_EQ(levelOf(0.5f, 65535.0), 32768);
  EXPECT_EQ(levelOf(-3.0f, 255.0), 0);
  EXPECT_EQ(levelOf(7.0f, 65535.0), 65535);
  EXPECT_EQ(levelOf(std::numeric_limits<float>::quiet_NaN(), 255.0), 0);
}

TEST(ImageLevels, QuantizesToTheNearestLevelWithoutGamma) {
  EXPECT_EQ(eightBitLevel(0.0f), 0);
  EXPECT_EQ(eightBitLevel(-3.0f), 0);
  EXPECT_EQ(eightBitLevel(1.0f), 255);
  EXPECT_EQ(eightBitLevel(7.0f), 255);
  EXPECT_EQ(eightBitLevel(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(eightBitLevel(0.25f), 64);  // 63.75
  EXPECT_EQ(eightBitLevel(0.2f), 51);
  EXPECT_EQ(eightBitLevel(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(ImageLevels, Quantizes16BitsToTheNearestLevel) {
  EXPECT_EQ(sixteenBitLevel(0.0f), 0);
  EXPECT_EQ(sixteenBitLevel(-2.0f), 0);
  EXPECT_EQ(sixteenBitLevel(1.0f), 65535);
  EXPECT_EQ(sixteenBitLevel(3.0f), 65535);
  EXPECT_EQ(sixteenBitLevel(0.5f), 32768);   // 32767.5 rounds up
  EXPECT_EQ(sixteenBitLevel(0.25f), 16384);  // 16383.75
}

// eightBitLevel rounds inline as std::lround rounds the same float product:
// every level's halfway point and its float neighbours, and a stride
// through all the floats of [0, 1].
TEST(ImageLevels, QuantizesAsLroundDoes) {
  auto byLround = [](float v) {
    return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  for (int level = 0; level < 255; ++level) {
    float half = (static_cast<float>(level) + 0.5f) / 255.0f;
    float v = half;
    for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
    for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) {
      ASSERT_EQ(eightBitLevel(v), byLround(v)) << v;
    }
  }
  for (std::uint32_t bits = 0; bits <= 0x3F800000u; bits += 997) {
    float v = std::bit_cast<float>(bits);
    ASSERT_EQ(eightBitLevel(v), byLround(v)) << v;
  }
}

// The vector loop gives each value the level that rounding in double gives,
// and eightBitLevel's: every level's halfway point and its float
// neighbours, and a stride through all 2^32 bit patterns (negatives,
// infinities and NaNs among them), in runs of 1 to 38 values, so that its
// tails are exercised too.
TEST(ImageLevels, QuantizesInBulkAsOneByOne) {
  std::vector<float> values;
  for (int level = 0; level < 256; ++level) {
    float v = (static_cast<float>(level) + 0.5f) / 255.0f;
    for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
    for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) values.push_back(v);
  }
  for (std::uint64_t bits = 0; bits <= 0xFFFFFFFFu; bits += 4099) {
    values.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
  }
  for (float special :
       {0.0f, -0.0f, 1.0f, std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
        std::numeric_limits<float>::denorm_min(), 0.5f / 255.0f}) {
    values.push_back(special);
  }
  std::vector<unsigned char> levels(values.size(), 0xAB);
  for (std::size_t first = 0, run = 1; first < values.size(); first += run, run = run % 37 + 2) {
    eightBitLevels(values.data() + first, std::min(run, values.size() - first),
                   levels.data() + first);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(levels[i], levelInDouble(values[i], 255.0)) << values[i];
    ASSERT_EQ(eightBitLevel(values[i]), levels[i]) << values[i];
  }
}

TEST(ImageLinear, SrgbDecodingMirrorsNegativesAndStaysWithinAFloat) {
  for (float v : {0.0f, 0.01f, 0.04045f, 0.5f, 1.0f, 2.0f}) {
    EXPECT_EQ(srgbToLinear(v), static_cast<float>(scene::srgbToLinear(v))) << v;
    EXPECT_EQ(srgbToLinear(-v), -srgbToLinear(v)) << v;
  }
  constexpr float kLargest = std::numeric_limits<float>::max();
  EXPECT_EQ(srgbToLinear(kLargest), kLargest);
  EXPECT_EQ(srgbToLinear(-std::numeric_limits<float>::infinity()), -kLargest);
}

}  // namespace
}  // namespace render
