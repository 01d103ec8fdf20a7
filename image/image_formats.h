// The image formats sfrender writes and how each stores the numbers it
// computes (docs/RENDERING.md, "Image files"): the list comes from
// OpenImageIO at run time (oiio_module.h), what sfrender does with each
// format from the table in image_formats.cpp.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace image {

// One format, with what sfrender stores in it.
struct ImageFormat {
  std::string name;                     // OpenImageIO's ("png", "openexr"), or "ppm" (sfrender's)
  std::vector<std::string> extensions;  // what names it, lower case with the dot: ".png"
  bool alpha = false;                   // whether it stores a fourth channel
  // Floating point holding linear values (EXR, HDR); otherwise integers
  // holding the display values, tagged sRGB.
  bool linear = false;
  std::vector<int> bits;  // the --bits it takes, its default first
};

// What sfrender asks of the image beyond its format.
struct ImageOptions {
  int bits = 0;        // bits a channel; 0: the format's default
  bool alpha = false;  // a fourth channel: the pixel's coverage (render::Image::coverage)
};

// .ppm, which sfrender writes itself (binary PPM, 8 or 16 bits), without
// OpenImageIO.
ImageFormat ppmFormat();

// .png, which sfrender writes itself with libpng (png_file.h), 8 or 16
// bits, with alpha, without OpenImageIO.
ImageFormat pngFormat();

// The formats of the module's list (oiio_module.h, SfrenderOiioFormats),
// with sfrender's own .ppm and .png first (.ppm taken out of the list's own
// "pnm" row, and the list's "png" row left out).
std::vector<ImageFormat> imageFormatsFrom(std::string_view moduleList);

// The format whose extension `path` has, in any case (".PNG" too), or null.
const ImageFormat* findImageFormat(const std::vector<ImageFormat>& formats,
                                   const std::filesystem::path& path);

// Every extension, for a message: ".ppm, .png, ... or .webp".
std::string imageExtensionsOf(const std::vector<ImageFormat>& formats);

// A table of the formats for --help: the extensions, the --bits each takes,
// whether it takes --alpha and how it stores colour.
std::string imageFormatTable(const std::vector<ImageFormat>& formats);

// The bits a channel `options` ask for in `format`: options.bits, or the
// format's default.
int storedBits(const ImageFormat& format, const ImageOptions& options);

// Why `format`, one of `formats`, cannot hold the image `options` ask for
// (a --bits it does not take, --alpha where it has no alpha), naming what
// it takes, or nothing.
std::optional<std::string> imageOptionsRefusal(const std::vector<ImageFormat>& formats,
                                               const ImageFormat& format,
                                               const ImageOptions& options);

}  // namespace image
