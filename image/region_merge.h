// Putting the regions of one image back together (sfrender --merge): the
// EXR files that `sfrender --tile i/N` or `--region` write, each a data
// window of the same display window, become the whole image, exactly the
// pixels that one render of it gives (docs/SCALING.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image.h"
#include "tools/common/tool_failure.h"

namespace image {

// The display value that sfrender's EXR writer turned into `linear`: the
// smallest float whose sRGB decoding (srgbToLinear) is `linear`, or, when
// none decodes to it exactly, the smallest whose decoding is above it.
// Negative values decode as srgbToLinear's do, a NaN gives 0. Exact for
// every value the writer makes: writing the result again gives `linear`
// bit for bit. Every float that decodes to `linear` has the same 8-bit
// level but at two of the 255 boundaries between levels (and 512 of the
// 65535 of 16 bits), where the float just below a level's first decodes to
// the same value (region_merge_test.cpp): so an 8-bit image made from the
// merge is the one a single render makes unless a display value is one of
// those two floats (docs/SCALING.md, "Exactness").
float displayFromLinear(float linear);

// The whole image from its regions, read from `files` (readImageRegion,
// image_file.h: regular files only, the display window at most `maxPixels`,
// --max-pixels, as for a render): every file must have the same display
// window, hold 32-bit floating-point RGB (the values exactly as rendered),
// and together they must cover the display window; where two overlap (a file
// named twice too), they must agree. A failure when they do not: a file
// that could not be read has the status of an I/O error, files that do not
// make one image that of invalid input.
tools::Outcome<render::Image> mergeImageRegions(const std::vector<std::filesystem::path>& files,
                                                std::int64_t maxPixels);

}  // namespace image
