#include "image/quantize.h"

#include "renderer/image.h"

namespace image {

unsigned char quantizeChannel(float value) {
  return render::eightBitLevel(value);
}

void quantizeChannels(const float* values, std::size_t count, unsigned char* levels) {
  render::eightBitLevels(values, count, levels);
}

std::uint16_t quantizeChannel16(float value) {
  return static_cast<std::uint16_t>(render::levelOf(value, 65535.0));
}

}  // namespace image
