// The integer levels of a display value, in the image writers' terms: the
// renderer's levels (renderer/image.h, levelOf), so that sfrender's integer
// images (PNG, TIFF, PPM), sfbuild's ray-traced view and the render's
// retracing agree to the level.
#pragma once

#include <cstddef>
#include <cstdint>

namespace image {

// The 8-bit level of a display value: render::eightBitLevel.
unsigned char quantizeChannel(float value);

// quantizeChannel of each of `count` values, into `levels`, in vector
// instructions: render::eightBitLevels.
void quantizeChannels(const float* values, std::size_t count, unsigned char* levels);

// The 16-bit level of a display value: render::levelOf(value, 65535).
std::uint16_t quantizeChannel16(float value);

}  // namespace image
