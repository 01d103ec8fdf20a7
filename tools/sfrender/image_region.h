// --region and --tile: the part of the image sfrender renders
// (docs/RENDERING.md, "Regions and tiles").
#pragma once

#include <optional>
#include <string>

#include "renderer/image.h"
#include "tools/common/cli_forward.h"
#include "tools/common/tool_failure.h"

namespace tools {

// "x0,y0,x1,y1": four whole numbers, half-open pixel bounds; nothing for any
// other text (the bounds themselves are not checked).
std::optional<render::PixelRegion> parseRegion(const std::string& text);

// "i/N": tile i (0-based) of N.
struct TileChoice {
  int index = 0;
  int count = 1;
};
std::optional<TileChoice> parseTile(const std::string& text);

// --region's check on the command line: four whole numbers x0,y0,x1,y1, x0
// and y0 not negative, the region not empty.
CLI::Validator regionOption();

// --tile's check: i/N with N at least 1 and 0 <= i < N.
CLI::Validator tileOption();

// A usage failure when --region's `region` does not lie within a `width` x
// `height` image.
MaybeFailure regionRefusal(const render::PixelRegion& region, int width, int height);

// A usage failure when --tile's `tile` of an image `height` rows high has no
// region (render::imageTile: horizontal bands): more bands than rows.
MaybeFailure tileRefusal(const TileChoice& tile, int height);

}  // namespace tools
