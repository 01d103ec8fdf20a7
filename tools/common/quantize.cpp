#include "tools/common/quantize.h"

#include <algorithm>
#include <cmath>

namespace tools {

unsigned char quantizeChannel(float value) {
  float clamped = std::clamp(value, 0.0f, 1.0f);
  return static_cast<unsigned char>(std::lround(clamped * 255.0f));
}

std::uint16_t quantizeChannel16(float value) {
  double clamped = std::clamp(static_cast<double>(value), 0.0, 1.0);
  return static_cast<std::uint16_t>(std::lround(clamped * 65535.0));
}

}  // namespace tools
