#include "renderer/image.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scenefile/srgb.h"

namespace render {

PixelRegion imageTile(int width, int height, int index, int count) {
  if (width <= 0 || height <= 0 || count <= 0 || index < 0 || index >= count || count > height) {
    return PixelRegion{};
  }
  // The first height % count bands are one row taller.
  int base = height / count;
  int taller = height % count;
  int y0 = index * base + std::min(index, taller);
  int y1 = y0 + base + (index < taller ? 1 : 0);
  return PixelRegion{0, y0, width, y1};
}

void eightBitLevels(const float* values, std::size_t count, unsigned char* levels) {
  for (std::size_t i = 0; i < count; ++i) levels[i] = eightBitLevel(values[i]);
}

long levelOf(float v, double levels) {
  if (levels == 255.0) return eightBitLevel(v);
  return std::lround(static_cast<double>(std::clamp(v, 0.0f, 1.0f)) * levels);
}

float srgbToLinear(float display) {
  double linear = scene::srgbToLinear(std::abs(static_cast<double>(display)));
  constexpr double kLargest = std::numeric_limits<float>::max();
  return static_cast<float>(std::copysign(std::min(linear, kLargest), display));
}

}  // namespace render
