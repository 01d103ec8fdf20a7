// The integer levels of a display value: how sfrender's integer images (PNG,
// TIFF, PPM) store a channel, and how sfbuild's ray-traced view shows one,
// so that the two agree to the level.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tools {

// The 8-bit level of a display value: round(clamp(v, 0, 1) * 255).
unsigned char quantizeChannel(float value);

// quantizeChannel of each of `count` values, into `levels`: the same
// levels, in a loop the compiler turns into vector instructions (one call
// per channel was 2.6% of a 1080p render's instructions, and writing its
// PPM 5 to 7% of its CPU time).
void quantizeChannels(const float* values, std::size_t count, unsigned char* levels);

// The 16-bit level of a display value: round(clamp(v, 0, 1) * 65535).
std::uint16_t quantizeChannel16(float value);

}  // namespace tools
