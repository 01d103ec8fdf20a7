// The integer levels of a display value: how sfrender's integer images (PNG,
// TIFF, PPM) store a channel, and how sfbuild's ray-traced view shows one,
// so that the two agree to the level.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tools {

// The 8-bit level of a display value: round(clamp(v, 0, 1) * 255).
unsigned char quantizeChannel(float value);

// quantizeChannel of each of `count` values, into `levels`, in a loop the
// compiler turns into vector instructions (a call a channel was 1.6% of
// the instructions of a render of floor-1000 at 1080p, whose PPM took
// 20 ms to write, 16 ms with this). quantizeChannel is this for one value.
void quantizeChannels(const float* values, std::size_t count, unsigned char* levels);

// The 16-bit level of a display value: round(clamp(v, 0, 1) * 65535).
std::uint16_t quantizeChannel16(float value);

}  // namespace tools
