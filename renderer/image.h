// A rendered image (scenefile/render.h's RenderedImage), the tiles a
// render hands out, and how its values become the levels of an integer image
// or the linear values of a float one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scenefile/render.h"

namespace render {

// A rectangle of pixels of the full image (scenefile/render.h).
using PixelRegion = scene::PixelRegion;

// The side, in pixels, of the square tiles that a render hands out to its
// threads (the last in a row or column cut at the region's edge).
inline constexpr int kRenderTileSize = 32;

// Tile `index` (0-based) of `count` of a `width` x `height` image: the
// index-th of `count` horizontal bands of whole rows, from the top, their
// heights differing by at most 1 (the taller first). Empty where the index
// is out of range or there are more bands than rows.
PixelRegion imageTile(int width, int height, int index, int count);

// The colours RENDERING.md computes, row by row from the top, three floats
// a pixel: the public image (scenefile/render.h).
using Image = scene::RenderedImage;

// The 8-bit level of a display value: round(clamp(v, 0, 1) * 255), halves
// up, not a number giving 0. The product is rounded in float, as every
// 8-bit image has been written; inline and branch-free so that a loop of it
// becomes vector instructions (eightBitLevels).
inline unsigned char eightBitLevel(float v) {
  // Selects that vectorise: a NaN fails `v > 0`.
  float positive = v > 0.0f ? v : 0.0f;
  float level = (positive < 1.0f ? positive : 1.0f) * 255.0f;
  // Halves up, as std::lround rounds a value of at least 0: the level less
  // its whole part is exact.
  int whole = static_cast<int>(level);
  float fraction = level - static_cast<float>(whole);
  return static_cast<unsigned char>(whole + (fraction >= 0.5f ? 1 : 0));
}

// eightBitLevel of each of `count` values, into `levels`: a call a channel
// was 1.6% of the instructions of a render of floor-1000 at 1080p, whose
// PPM took 20 ms to write, 16 ms with this loop.
void eightBitLevels(const float* values, std::size_t count, unsigned char* levels);

// The level of a display value in an integer image whose largest level is
// `levels` (255 for 8 bits, 65535 for 16): round(clamp(v, 0, 1) * levels),
// eightBitLevel's for 255. What the render's retracing keeps exact
// (RenderSettings::levels) and what the image writers store.
long levelOf(float v, double levels);

// The 16-bit level of a display value: levelOf(v, 65535).
inline std::uint16_t sixteenBitLevel(float v) {
  return static_cast<std::uint16_t>(levelOf(v, 65535.0));
}

// The linear value of a display value, what a float image file (EXR, HDR)
// stores: sRGB's decoding (scene::srgbToLinear), extended past [0, 1] as in
// scRGB (IEC 61966-2-2) and extended sRGB: the power segment goes on above
// 1, and a negative value decodes to minus the decoding of its magnitude.
// Within the float range: the largest float stands for anything larger.
float srgbToLinear(float display);

}  // namespace render
