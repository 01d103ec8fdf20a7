#include "tools/common/quantize.h"

#include <algorithm>
#include <cmath>

namespace tools {

unsigned char quantizeChannel(float value) {
  float level = std::clamp(value, 0.0f, 1.0f) * 255.0f;
  // std::lround of the float product, inline (a library call per channel
  // was 3% of a render): a float plus 0.5 is exact in double, and at 0.5
  // or more truncation is its floor, so this rounds halves up as lround
  // does for a value of at least 0.
  if (!(level >= 0.0f)) return 0;
  return static_cast<unsigned char>(static_cast<int>(static_cast<double>(level) + 0.5));
}

void quantizeChannels(const float* values, std::size_t count, unsigned char* levels) {
  for (std::size_t i = 0; i < count; ++i) {
    // The clamp of quantizeChannel, with not a number to 0 as it gives,
    // written as selects that vectorise: a NaN fails `v > 0`.
    float v = values[i];
    float positive = v > 0.0f ? v : 0.0f;
    float level = (positive < 1.0f ? positive : 1.0f) * 255.0f;
    // Halves up, in float: the level less its whole part is exact.
    int whole = static_cast<int>(level);
    float fraction = level - static_cast<float>(whole);
    levels[i] = static_cast<unsigned char>(whole + (fraction >= 0.5f ? 1 : 0));
  }
}

std::uint16_t quantizeChannel16(float value) {
  double clamped = std::clamp(static_cast<double>(value), 0.0, 1.0);
  return static_cast<std::uint16_t>(std::lround(clamped * 65535.0));
}

}  // namespace tools
