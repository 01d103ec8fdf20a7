// The integer levels of a display value: how sfrender's integer images (PNG,
// TIFF, PPM) store a channel, and how sfbuild's ray-traced view shows one,
// so that the two agree to the level.
#pragma once

#include <cstdint>

namespace tools {

// The 8-bit level of a display value: round(clamp(v, 0, 1) * 255).
unsigned char quantizeChannel(float value);

// The 16-bit level of a display value: round(clamp(v, 0, 1) * 65535).
std::uint16_t quantizeChannel16(float value);

}  // namespace tools
