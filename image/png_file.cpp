#include "image/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <new>
#include <vector>

namespace image {

namespace {

// Where libpng's output goes, and the first error it reports. Plain data:
// libpng reports errors by longjmp, which must not cross the destructor of
// a live C++ object, so everything that owns memory lives in the caller.
struct PngSink {
  std::string* bytes = nullptr;
  char message[256] = "";
};

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  try {
    sink->bytes->append(reinterpret_cast<const char*>(data), length);
  } catch (const std::bad_alloc&) {
    png_error(png, "out of memory");
  }
}

void flushNothing(png_structp) {}

void recordError(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::strncpy(sink->message, message ? message : "", sizeof sink->message - 1);
  png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

// Writes the image with libpng into sink->bytes; false on an error, whose
// message is in sink->message. `rows` points at each row's first level.
bool writePng(const PngLevels& levels, png_bytep* rows, PngSink& sink) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, recordError, ignoreWarning);
  if (!png) {
    std::strcpy(sink.message, "libpng could not start");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    if (!info && !sink.message[0]) std::strcpy(sink.message, "libpng could not start");
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, &sink, appendBytes, flushNothing);
  int colourType = levels.channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB;
  png_set_IHDR(png, info, static_cast<png_uint_32>(levels.width),
               static_cast<png_uint_32>(levels.height), levels.bits, colourType, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Every row unfiltered, at zlib's level 2: a rendered image's pixel-to-
  // pixel noise leaves the filters' differences no easier to compress than
  // the bytes. Against the Sub filter at level 3, at 1920x1080 (floor-
  // 1000000, 1 sample) 0.07 s instead of 0.16 s and 1,926,599 bytes instead
  // of 2,541,007; at 1280x720 the default scene 136,809 bytes (141,227) and
  // floor-1000 419,627 (426,641) in two thirds of the time. Level 3 saved
  // 1.5% more bytes for 30% more time. docs/RENDERING.md, "Image files".
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, 2);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (levels.originX != 0 || levels.originY != 0) {
    png_set_oFFs(png, info, levels.originX, levels.originY, PNG_OFFSET_PIXEL);
  }
  png_write_info(png, info);
  // PNG's 16-bit samples are big-endian; the levels are in host order.
  if (levels.bits == 16) png_set_swap(png);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

tools::Outcome<std::string> pngFileBytes(const PngLevels& levels) {
  std::string bytes;
  std::size_t rowLevels = static_cast<std::size_t>(levels.width) * levels.channels;
  std::vector<png_bytep> rows(static_cast<std::size_t>(levels.height));
  for (std::size_t y = 0; y < rows.size(); ++y) {
    const void* row = levels.bits == 16 ? static_cast<const void*>(levels.words + y * rowLevels)
                                        : static_cast<const void*>(levels.bytes + y * rowLevels);
    // libpng reads the rows without writing them (png_write_image).
    rows[y] = static_cast<png_bytep>(const_cast<void*>(row));
  }
  PngSink sink;
  sink.bytes = &bytes;
  if (!writePng(levels, rows.data(), sink)) {
    return tools::toolFailure(tools::ExitCode::IoError,
                              sink.message[0] ? sink.message : "libpng failed");
  }
  return bytes;
}

}  // namespace image
