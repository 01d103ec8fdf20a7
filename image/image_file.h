// Writing a rendered image in the format its file name asks for, so that
// every format shows the same picture in a colour-managed viewer
// (docs/RENDERING.md, "Image files").
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image_formats.h"
#include "image/oiio_module.h"
#include "renderer/image.h"
#include "renderer/render_settings.h"
#include "tools/common/tool_failure.h"

namespace image {

// The formats sfrender writes: .ppm, and those OpenImageIO's module
// offers (oiio_module.h), or .ppm alone when the module cannot be loaded.
std::vector<ImageFormat> writableImageFormats();

// Whether files with this name's extension can be written: ".ppm" here and
// every other through OpenImageIO (whose module must load and take it).
bool canWriteImage(const std::filesystem::path& path);

// A usage failure when an image cannot be written to `path` as `options`
// ask: an extension no writer takes (with the list of those that do),
// OpenImageIO's module that could not be loaded (from where and why; .ppm
// needs none), or a --bits or --alpha the format cannot hold; nothing when
// it can.
tools::MaybeFailure imageRefusal(const std::filesystem::path& path,
                                 const ImageOptions& options = {});

// The render that the image at `path` needs: the coverage for --alpha, and
// for a 16-bit integer image, retracing to its levels (and a tolerance of
// half of one), so that each level is what full tracing gives, as for 8
// bits (docs/RENDERING.md, "Cost").
void fitRenderToImage(const std::filesystem::path& path, const ImageOptions& options,
                      render::RenderSettings& settings);

// The formats sfrender writes, for --help: from OpenImageIO's module, or
// .ppm alone with why the module could not be loaded.
std::string imageFormatHelp();

// The bytes of a width x height image written to `path` when it is a ".ppm"
// (the header and three channels a pixel, one or two bytes each); 0 for
// another format, whose size is known only once written.
std::uint64_t ppmFileSize(int width, int height, const std::filesystem::path& path,
                          const ImageOptions& options = {});

// Writes the image: integer formats get the display values (clamped to
// [0, 1], rounded to the nearest level, no gamma) tagged sRGB; EXR and HDR
// the linear values (srgbToLinear); with options.alpha a fourth channel
// from the image's coverage, straight in integer formats, premultiplied in
// floating-point ones. PPM is written by hand, every other format through
// OpenImageIO (into memory, memory_file.h). The bytes are then written
// beside the target under a temporary name, each write checked, flushed and
// renamed (file_io.h), so the file appears whole or not at all: on a full
// disk the old file stays as it was.
// With `replace` false (--no-clobber), an existing file is kept and the
// write fails. A failure is "cannot write the image: WHY" about `path`,
// with the status of a file that cannot be written.
tools::MaybeFailure writeImageFile(const render::Image& image, const std::filesystem::path& path,
                                   const ImageOptions& options = {}, bool replace = true);

// The bytes of the image as binary PPM (P6, 8 or 16 bits as options.bits
// says): what a ".ppm" file holds, and what `sfrender -o -` writes to
// standard output.
std::string ppmImageBytes(const render::Image& image, const ImageOptions& options = {});

// A region of an image read back from a file (sfrender --merge): its data
// and display windows, and its first three channels as floats, row by row.
struct ImageRegionFile {
  SfrenderImageRegion region{};
  std::vector<float> rgb;
};

// What a region to merge must be, for the messages that refuse one.
inline constexpr const char* kRegionsAreFloatExr =
    "regions to merge are 32-bit float EXR, which hold the render exactly (render them with -o "
    "NAME.exr and no --bits)";

// Reads the OpenEXR file at `path` through OpenImageIO's module as a region to
// merge, bounded as a render is: only a regular file is opened; its windows
// and channels are checked, in arithmetic that cannot overflow, before a
// pixel is allocated (3 or 4 channels, the data window inside the display
// window, which holds at most `maxPixels` pixels); and every value read must
// be finite, as every value a render writes is. A failure is "cannot read
// 'PATH': ..." with the status of a file that cannot be read, or "'PATH' ..."
// with that of invalid input when the file holds what cannot be merged.
tools::Outcome<ImageRegionFile> readImageRegion(const std::filesystem::path& path,
                                                std::int64_t maxPixels);

// The same through `read`, the module's reader (oiio_module.h), for a
// program that links the module's code in (the fuzz target).
tools::Outcome<ImageRegionFile> readImageRegionWith(SfrenderOiioRead read,
                                                    const std::filesystem::path& path,
                                                    std::int64_t maxPixels);

// The linear value of a display value, as float images store it.
using render::srgbToLinear;

}  // namespace image
