// PNG written with libpng itself, not through OpenImageIO: PNG is the
// format most renders are written in, and loading OpenImageIO (its module
// and every library it links: OpenEXR, OpenVDB, libheif, FFmpeg...) cost
// 0.21 s of CPU a run on this project's machines, more than rendering a
// small scene; libpng, which OpenImageIO's own PNG writer calls, costs
// about a millisecond to load. docs/RENDERING.md, "Image files".
#pragma once

#include <cstdint>
#include <string>

#include "tools/common/tool_failure.h"

namespace image {

// The levels of an image in the order PNG stores them: rows from the top,
// `channels` (3: RGB, 4: RGBA with straight alpha) a pixel, each an 8-bit
// level (`bytes`) or a 16-bit one (`words`, host order), as `bits` says.
struct PngLevels {
  int width = 0;
  int height = 0;
  int channels = 3;
  int bits = 8;
  const unsigned char* bytes = nullptr;
  const std::uint16_t* words = nullptr;
  // Where the image lies in a larger one (a region of a render): written
  // as the oFFs chunk, in pixels, when not 0, 0, as OpenImageIO does.
  int originX = 0;
  int originY = 0;
};

// The bytes of a PNG file of `levels`, tagged sRGB (the sRGB chunk, with
// gAMA and cHRM for readers that know no sRGB: the PNG specification's
// advice), or libpng's reason it could not (ExitCode::IoError, as a write's).
tools::Outcome<std::string> pngFileBytes(const PngLevels& levels);

}  // namespace image
