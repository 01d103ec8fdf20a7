#include "image/png_file.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstring>
#include <new>
#include <vector>

#include "image/deflate_pieces.h"

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

// Row y of the image as PNG's filtered data, into `out`: its filter type,
// 0 (none), then its levels, 16-bit ones most significant byte first.
void filteredRow(const PngLevels& levels, std::size_t y, unsigned char* out) {
  std::size_t rowLevels = static_cast<std::size_t>(levels.width) * levels.channels;
  *out++ = 0;
  if (levels.bits == 16) {
    const std::uint16_t* row = levels.words + y * rowLevels;
    for (std::size_t k = 0; k < rowLevels; ++k) {
      *out++ = static_cast<unsigned char>(row[k] >> 8);
      *out++ = static_cast<unsigned char>(row[k] & 0xff);
    }
  } else {
    std::memcpy(out, levels.bytes + y * rowLevels, rowLevels);
  }
}

// The image data's zlib stream: every row unfiltered, at zlib's level 2,
// in pieces of a megabyte or more deflated on every core (deflate_pieces.h).
// A rendered image's pixel-to-pixel noise leaves the filters' differences
// no easier to compress than the bytes: against the Sub filter at level 3,
// at 1920x1080 (floor-1000000, 1 sample) half the time and 1,926,599 bytes
// instead of 2,541,007. The pieces, each without its predecessor's history,
// cost nothing there (1,926,171 bytes in 6, as libpng's own deflate
// settings differ), and level 1 saved no time. Level 3 saved 1.5% more
// bytes for 30% more time. docs/RENDERING.md, "Image files".
std::string imageData(const PngLevels& levels) {
  PieceSource source;
  source.units = static_cast<std::size_t>(levels.height);
  source.unitBytes =
      1 + static_cast<std::size_t>(levels.width) * levels.channels * (levels.bits == 16 ? 2 : 1);
  source.unit = [&levels](std::size_t y, unsigned char* scratch) {
    filteredRow(levels, y, scratch);
    return static_cast<const unsigned char*>(scratch);
  };
  return deflatePieces(source, 2, 0);
}

// Writes the PNG file of `levels`, whose image data is `data` (a zlib
// stream, imageData), with libpng into sink->bytes; false on an error,
// whose message is in sink->message. libpng writes the signature and every
// chunk but IDAT's contents, which are deflated apart on several threads.
bool writePng(const PngLevels& levels, const std::string& data, PngSink& sink) {
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
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (levels.originX != 0 || levels.originY != 0) {
    png_set_oFFs(png, info, levels.originX, levels.originY, PNG_OFFSET_PIXEL);
  }
  png_write_info(png, info);
  // IDAT chunks of at most a gigabyte (a chunk holds less than 2 GiB): one
  // stream split anywhere, as a reader joins them.
  constexpr std::size_t kMaxChunk = std::size_t{1} << 30;
  const auto* bytes = reinterpret_cast<png_const_bytep>(data.data());
  for (std::size_t first = 0; first < data.size(); first += kMaxChunk) {
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), bytes + first,
                    std::min(kMaxChunk, data.size() - first));
  }
  png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

tools::Outcome<std::string> pngFileBytes(const PngLevels& levels) {
  std::string bytes;
  PngSink sink;
  sink.bytes = &bytes;
  try {
    std::string data = imageData(levels);
    bytes.reserve(data.size() + 4096);
    if (data.empty()) {
      return tools::toolFailure(tools::ExitCode::IoError, "zlib could not compress the image");
    }
    if (writePng(levels, data, sink)) return bytes;
  } catch (const std::bad_alloc&) {
    return tools::toolFailure(tools::ExitCode::IoError, "out of memory");
  }
  return tools::toolFailure(tools::ExitCode::IoError,
                            sink.message[0] ? sink.message : "libpng failed");
}

}  // namespace image
