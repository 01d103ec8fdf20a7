#include "image/quantize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace image {
namespace {

TEST(ImageFile, QuantizesToTheNearestLevelWithoutGamma) {
  EXPECT_EQ(quantizeChannel(0.0f), 0);
  EXPECT_EQ(quantizeChannel(-3.0f), 0);
  EXPECT_EQ(quantizeChannel(1.0f), 255);
  EXPECT_EQ(quantizeChannel(7.0f), 255);
  EXPECT_EQ(quantizeChannel(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(quantizeChannel(0.25f), 64);  // 63.75
  EXPECT_EQ(quantizeChannel(0.2f), 51);
  EXPECT_EQ(quantizeChannel(std::numeric_limits<float>::quiet_NaN()), 0);
}

// quantizeChannel rounds inline as std::lround rounds the same float
// product: every level's halfway point and its float neighbours, and a
// stride through all the floats of [0, 1].
TEST(ImageFile, QuantizesAsLroundDoes) {
  auto byLround = [](float v) {
    return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  for (int level = 0; level < 255; ++level) {
    float half = (static_cast<float>(level) + 0.5f) / 255.0f;
    float v = half;
    for (int step = 0; step < 8; ++step) v = std::nextafter(v, 0.0f);
    for (int step = 0; step < 16; ++step, v = std::nextafter(v, 2.0f)) {
      ASSERT_EQ(quantizeChannel(v), byLround(v)) << v;
    }
  }
  for (std::uint32_t bits = 0; bits <= 0x3F800000u; bits += 997) {
    float v = std::bit_cast<float>(bits);
    ASSERT_EQ(quantizeChannel(v), byLround(v)) << v;
  }
}

// quantizeChannels (which quantizeChannel calls for one value) gives each
// value the level that rounding in double gives, apart from its float
// steps: every level's halfway point and its float neighbours, and a
// stride through all 2^32 bit patterns (negatives, infinities and NaNs
// among them), in runs of 1 to 38 values, so that the vector loop's tails
// are exercised too.
TEST(ImageFile, QuantizesInBulkAsOneByOne) {
  // A float plus 0.5 is exact in double, and its truncation rounds halves
  // up for a value of at least 0; not a number gives 0.
  auto byDouble = [](float v) {
    float level = std::clamp(v, 0.0f, 1.0f) * 255.0f;
    if (!(level >= 0.0f)) return static_cast<unsigned char>(0);
    return static_cast<unsigned char>(static_cast<int>(static_cast<double>(level) + 0.5));
  };
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
    std::size_t count = std::min(run, values.size() - first);
    quantizeChannels(values.data() + first, count, levels.data() + first);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(levels[i], byDouble(values[i])) << values[i];
    ASSERT_EQ(quantizeChannel(values[i]), levels[i]) << values[i];
  }
}

}  // namespace
}  // namespace image
