#include "image/quantize.h"

#include <algorithm>
#include <cmath>

namespace tools {

unsigned char quantizeChannel(float value) {
  unsigned char level = 0;
  quantizeChannels(&value, 1, &level);
  return level;
}

void quantizeChannels(const float* values, std::size_t count, unsigned char* levels) {
  for (std::size_t i = 0; i < count; ++i) {
    // round(clamp(v, 0, 1) * 255), not a number giving 0, written as
    // selects that vectorise: a NaN fails `v > 0`.
    float v = values[i];
    float positive = v > 0.0f ? v : 0.0f;
    float level = (positive < 1.0f ? positive : 1.0f) * 255.0f;
    // Halves up, as std::lround rounds a value of at least 0, in float:
    // the level less its whole part is exact.
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
