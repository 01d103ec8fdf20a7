#include "image/image_file.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "image/exr_header.h"
#include "image/memory_file.h"
#include "image/oiio_module.h"
#include "image/png_file.h"
#include "tools/common/file_io.h"
#include "scenefile/printable_text.h"

namespace image {

namespace {

// A step of writing an image that failed, with the reason alone;
// writeImageFile says which file and what it was doing.
tools::ToolFailure cannotWrite(std::string why) {
  return tools::toolFailure(tools::ExitCode::IoError, std::move(why));
}

// The functions of the OpenImageIO module (oiio_module.h).
struct OiioModule {
  SfrenderOiioFormats formats = nullptr;
  SfrenderOiioWrite write = nullptr;
  SfrenderOiioRead read = nullptr;
};

#ifndef SFRENDER_MODULE_DIR
#define SFRENDER_MODULE_DIR "../lib/scenefile"
#endif

// The module's file: in SFRENDER_MODULE_DIR (tools/CMakeLists.txt: the
// prefix's lib/scenefile/ seen from its bin/), relative to the folder of the
// running program as /proc/self/exe names it, so that an installed prefix
// works wherever it is moved; the build folder has the same layout. Empty
// when the program's own path cannot be read.
std::filesystem::path oiioModulePath() {
  std::error_code failed;
  std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", failed);
  if (failed || program.empty()) return {};
  return (program.parent_path() / SFRENDER_MODULE_DIR / "sfrender_oiio.so").lexically_normal();
}

// Why the module did not load, for a message that says where it was looked for.
std::string moduleFailure(const std::filesystem::path& file, const std::string& why) {
  if (file.empty()) {
    return "OpenImageIO's module (sfrender_oiio.so), which writes every format but .ppm and .png, "
           "could "
           "not be loaded: the program's own path (/proc/self/exe), which it is found from, "
           "cannot be read";
  }
  std::string reason = why;
  std::string prefix = file.string() + ": ";
  if (reason.compare(0, prefix.size(), prefix) == 0) reason.erase(0, prefix.size());
  return "OpenImageIO's module, which writes every format but .ppm and .png, could not be loaded "
         "from " +
         file.string() + (reason.empty() ? "" : " (" + reason + ")");
}

// Loads the module (oiioModulePath). dlopen counts its loads, so a second
// call is cheap; the module is never unloaded, as OpenImageIO's threads may
// outlive a write.
std::optional<OiioModule> loadOiio(std::string& error) {
  std::filesystem::path file = oiioModulePath();
  if (file.empty()) {
    error = moduleFailure(file, "");
    return std::nullopt;
  }
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    error = moduleFailure(file, why ? why : "");
    return std::nullopt;
  }
  OiioModule m;
  m.formats = reinterpret_cast<SfrenderOiioFormats>(::dlsym(handle, SFRENDER_OIIO_FORMATS));
  m.write = reinterpret_cast<SfrenderOiioWrite>(::dlsym(handle, SFRENDER_OIIO_WRITE));
  m.read = reinterpret_cast<SfrenderOiioRead>(::dlsym(handle, SFRENDER_OIIO_READ));
  if (!m.formats || !m.write || !m.read) {
    error = moduleFailure(file, "it lacks its functions");
    return std::nullopt;
  }
  return m;
}

// The formats sfrender can write: .ppm and .png, and those of OpenImageIO when its
// module loads (or why it did not, in `moduleError`).
struct Writable {
  std::optional<OiioModule> oiio;
  std::vector<ImageFormat> formats;
  std::string moduleError;
};

Writable writableFormats() {
  Writable w;
  w.oiio = loadOiio(w.moduleError);
  std::string list;
  if (w.oiio) {
    list.resize(w.oiio->formats(nullptr, 0) + 1);
    list.resize(w.oiio->formats(list.data(), list.size()));
  }
  w.formats = imageFormatsFrom(list);
  return w;
}

// Whether `path` ends in `extension` (".ppm"), in any case.
bool hasExtension(const std::filesystem::path& path, std::string_view extension) {
  std::string given = path.extension().string();
  return given.size() == extension.size() &&
         std::equal(given.begin(), given.end(), extension.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

// Binary PPM (P6) is written here rather than through OpenImageIO: the
// format is a header and the bytes, and OpenImageIO's writer, which writes
// it a scanline at a time behind its plugin lookup, cost 0.15 to 0.2 s on a
// 1920x1080 image.
bool isPpm(const std::filesystem::path& path) {
  return hasExtension(path, ".ppm");
}

// PNG is written with libpng (png_file.h), without loading OpenImageIO.
bool isPng(const std::filesystem::path& path) {
  return hasExtension(path, ".png");
}

// The formats sfrender writes without OpenImageIO's module, or null.
std::optional<ImageFormat> ownFormat(const std::filesystem::path& path) {
  if (isPpm(path)) return ppmFormat();
  if (isPng(path)) return pngFormat();
  return std::nullopt;
}

std::string ppmHeader(int width, int height, int bits) {
  return "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n" +
         (bits == 16 ? "65535" : "255") + "\n";
}

// The channels a pixel of the file: RGB, and alpha with --alpha.
int channelsOf(const ImageOptions& options) {
  return options.alpha ? 4 : 3;
}

// The display values as levels, a pixel's colour straight (divided by its
// coverage) when the file gets alpha: integer formats store alpha straight
// (PNG must; TIFF marks it unassociated), so that the levels of a covered
// pixel are its colour's, whatever the coverage.
template <typename Level, typename Quantize>
std::vector<Level> displayLevels(const render::Image& image, const ImageOptions& options,
                                 Quantize quantize) {
  std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  int channels = channelsOf(options);
  std::vector<Level> levels(pixels * channels);
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* rgb = &image.rgb[3 * p];
    Level* out = &levels[channels * p];
    if (!options.alpha) {
      for (int c = 0; c < 3; ++c) out[c] = quantize(rgb[c]);
      continue;
    }
    float a = image.coverage[p];
    for (int c = 0; c < 3; ++c) out[c] = quantize(a > 0.0f ? rgb[c] / a : 0.0f);
    out[3] = quantize(a);
  }
  return levels;
}

// displayLevels of an 8-bit file: without alpha, the image's values in one
// vector loop (render::eightBitLevels).
std::vector<unsigned char> displayBytes(const render::Image& image, const ImageOptions& options) {
  if (options.alpha) return displayLevels<unsigned char>(image, options, render::eightBitLevel);
  std::vector<unsigned char> bytes(image.rgb.size());
  render::eightBitLevels(image.rgb.data(), image.rgb.size(), bytes.data());
  return bytes;
}

// The linear values (srgbToLinear), within `largest` (a half's range for a
// half image: past it a half is infinite). With alpha they are
// premultiplied, as EXR's are by convention: the coverage times the
// decoding of the straight colour, which is what a colour-managed reader
// that unpremultiplies, converts and premultiplies again (OpenImageIO,
// Nuke) turns back into the straight display colour.
std::vector<float> linearValues(const render::Image& image, const ImageOptions& options,
                                float largest) {
  std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  int channels = channelsOf(options);
  auto linear = [largest](float v) { return std::clamp(srgbToLinear(v), -largest, largest); };
  std::vector<float> values(pixels * channels);
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* rgb = &image.rgb[3 * p];
    float* out = &values[channels * p];
    if (!options.alpha) {
      for (int c = 0; c < 3; ++c) out[c] = linear(rgb[c]);
      continue;
    }
    float a = image.coverage[p];
    for (int c = 0; c < 3; ++c) out[c] = a > 0.0f ? a * linear(rgb[c] / a) : 0.0f;
    out[3] = a;
  }
  return values;
}

std::string ppmBytes(const render::Image& image, int bits) {
  std::string header = ppmHeader(image.width, image.height, bits);
  std::string bytes = header;
  if (bits == 16) {
    // Most significant byte first (Netpbm).
    std::vector<std::uint16_t> levels =
        displayLevels<std::uint16_t>(image, {}, render::sixteenBitLevel);
    bytes.resize(header.size() + 2 * levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
      bytes[header.size() + 2 * i] = static_cast<char>(levels[i] >> 8);
      bytes[header.size() + 2 * i + 1] = static_cast<char>(levels[i] & 0xff);
    }
    return bytes;
  }
  bytes.resize(header.size() + image.rgb.size());
  render::eightBitLevels(image.rgb.data(), image.rgb.size(),
                         reinterpret_cast<unsigned char*>(bytes.data() + header.size()));
  return bytes;
}

tools::Outcome<std::string> pngBytes(const render::Image& image, const ImageOptions& options,
                                     int bits) {
  PngLevels levels;
  levels.width = image.width;
  levels.height = image.height;
  levels.channels = channelsOf(options);
  levels.bits = bits;
  levels.originX = image.originX;
  levels.originY = image.originY;
  std::vector<unsigned char> bytes;
  std::vector<std::uint16_t> words;
  if (bits == 16) {
    words = displayLevels<std::uint16_t>(image, options, render::sixteenBitLevel);
    levels.words = words.data();
  } else {
    bytes = displayBytes(image, options);
    levels.bytes = bytes.data();
  }
  return pngFileBytes(levels);
}

// Zeros past the last pixel, a row and 64 bytes of them, before the values
// are handed to OpenImageIO: its HEIF writer (2.4) copies a scanline by its
// own plane's stride, wider than the image's row, and so reads past the end
// of the image (AddressSanitizer: a row past a 64x20 image).
template <typename Value>
void padForWriters(std::vector<Value>& values, std::size_t rowValues) {
  values.resize(values.size() + rowValues + 64 / sizeof(Value));
}

// Writes through the module, as `format` stores the image, into `encoded`
// (memory_file.h): OpenImageIO's writers pick the format by `path`'s
// extension.
tools::MaybeFailure writeThroughOiio(const OiioModule& oiio, const render::Image& image,
                                     const ImageFormat& format, const ImageOptions& options,
                                     const std::filesystem::path& path, MemoryFile& encoded) {
  int bits = storedBits(format, options);
  SfrenderImageData data{image.width,
                         image.height,
                         channelsOf(options),
                         kSfrenderUint8,
                         nullptr,
                         0,
                         1,
                         image.originX,
                         image.originY,
                         image.fullWidth > 0 ? image.fullWidth : image.width,
                         image.fullHeight > 0 ? image.fullHeight : image.height};
  std::size_t rowValues = static_cast<std::size_t>(image.width) * channelsOf(options);
  std::vector<unsigned char> bytes;
  std::vector<std::uint16_t> words;
  std::vector<float> floats;
  if (format.linear) {
    constexpr float kLargestHalf = 65504.0f;
    data.pixelType = bits == 16 ? kSfrenderHalf : kSfrenderFloat;
    floats =
        linearValues(image, options, bits == 16 ? kLargestHalf : std::numeric_limits<float>::max());
    padForWriters(floats, rowValues);
    data.pixels = floats.data();
    data.linear = 1;
    data.straightAlpha = 0;
  } else if (bits == 16) {
    data.pixelType = kSfrenderUint16;
    words = displayLevels<std::uint16_t>(image, options, render::sixteenBitLevel);
    padForWriters(words, rowValues);
    data.pixels = words.data();
  } else {
    bytes = displayBytes(image, options);
    padForWriters(bytes, rowValues);
    data.pixels = bytes.data();
  }
  char message[512] = "";
  if (tools::MaybeFailure failure = encoded.create()) return failure;
  if (!oiio.write(path.c_str(), &data, encoded.descriptor(), message, sizeof message)) {
    return cannotWrite(message);
  }
  return std::nullopt;
}

// Why a region read back cannot be merged within `maxPixels`, as a sentence
// after the file's name, or nothing. In 64-bit arithmetic: a window's
// corner plus its size may pass the largest int.
std::optional<std::string> regionRefusal(const SfrenderImageRegion& r, std::int64_t maxPixels) {
  if (r.channels < 3 || r.channels > 4) {
    return " holds " + std::to_string(r.channels) +
           " channels; regions to merge hold 3 (RGB) or 4 (RGBA), as sfrender writes them";
  }
  auto window = [](std::int64_t x, std::int64_t y, std::int64_t width, std::int64_t height) {
    return std::to_string(width) + "x" + std::to_string(height) + " at " + std::to_string(x) + "," +
           std::to_string(y);
  };
  if (r.width <= 0 || r.height <= 0 || r.fullWidth <= 0 || r.fullHeight <= 0) {
    return " has an empty window (pixels " + window(r.x, r.y, r.width, r.height) + ", image " +
           window(r.fullX, r.fullY, r.fullWidth, r.fullHeight) + ")";
  }
  std::int64_t pixels = std::int64_t{r.fullWidth} * r.fullHeight;
  if (pixels > maxPixels) {
    return " is a region of a " + std::to_string(r.fullWidth) + "x" + std::to_string(r.fullHeight) +
           " image, " + std::to_string(pixels) + " pixels, more than the limit of " +
           std::to_string(maxPixels) + "; raise it with --max-pixels";
  }
  if (r.x < r.fullX || r.y < r.fullY ||
      std::int64_t{r.x} + r.width > std::int64_t{r.fullX} + r.fullWidth ||
      std::int64_t{r.y} + r.height > std::int64_t{r.fullY} + r.fullHeight) {
    return "'s pixels (" + window(r.x, r.y, r.width, r.height) + ") reach outside its image (" +
           window(r.fullX, r.fullY, r.fullWidth, r.fullHeight) + ")";
  }
  return std::nullopt;
}

// The first value of `file` that is not finite, with its pixel in the
// display window and its channel, or nothing.
std::optional<std::string> nonFiniteValue(const ImageRegionFile& file) {
  for (std::size_t i = 0; i < file.rgb.size(); ++i) {
    float v = file.rgb[i];
    if (std::isfinite(v)) continue;
    const SfrenderImageRegion& r = file.region;
    std::size_t pixel = i / 3;
    std::int64_t x = std::int64_t{r.x} - r.fullX + static_cast<std::int64_t>(pixel % r.width);
    std::int64_t y = std::int64_t{r.y} - r.fullY + static_cast<std::int64_t>(pixel / r.width);
    std::string channel(1, "RGB"[i % 3]);
    return std::string(std::isnan(v) ? "nan"
                       : v > 0       ? "inf"
                                     : "-inf") +
           " at pixel " + std::to_string(x) + "," + std::to_string(y) + " (its " + channel +
           " channel)";
  }
  return std::nullopt;
}

}  // namespace

std::vector<ImageFormat> writableImageFormats() {
  return writableFormats().formats;
}

tools::MaybeFailure imageRefusal(const std::filesystem::path& path, const ImageOptions& options) {
  auto refused = [](const std::string& message) {
    return tools::toolFailure(tools::ExitCode::Usage, scene::printableText(message));
  };
  // .ppm and .png need no module, unless to list the formats that take
  // --alpha or --bits in a refusal.
  if (std::optional<ImageFormat> own = ownFormat(path)) {
    if (!imageOptionsRefusal({*own}, *own, options)) return std::nullopt;
  }
  Writable w = writableFormats();
  const ImageFormat* format = findImageFormat(w.formats, path);
  if (!format) {
    return refused("cannot write images named '" + path.string() + "': " +
                   (w.oiio ? "use " + imageExtensionsOf(w.formats)
                           : w.moduleError + "; .ppm and .png need no module"));
  }
  if (std::optional<std::string> refusal = imageOptionsRefusal(w.formats, *format, options)) {
    return refused(
        "cannot write '" + path.string() + "' with " +
        (options.alpha && !format->alpha ? "--alpha" : "--bits " + std::to_string(options.bits)) +
        ": " + *refusal);
  }
  return std::nullopt;
}

bool canWriteImage(const std::filesystem::path& path) {
  return !imageRefusal(path);
}

void fitRenderToImage(const std::filesystem::path& path, const ImageOptions& options,
                      render::RenderSettings& settings) {
  settings.coverage = options.alpha;
  std::optional<ImageFormat> format = ownFormat(path);
  if (!format && options.bits == 16) {
    Writable w = writableFormats();
    if (const ImageFormat* found = findImageFormat(w.formats, path)) format = *found;
  }
  if (format && !format->linear && storedBits(*format, options) == 16) {
    settings.levels = 65535.0;
    settings.pruneTolerance = 0.5 / settings.levels;
  }
}

std::string imageFormatHelp() {
  Writable w = writableFormats();
  std::string help = "Image formats (by the extension of -o or OUTPUT_FILE):\n" +
                     imageFormatTable(w.formats) +
                     "  The first of the bits a channel is the default (16 in OpenEXR is half);\n"
                     "  sRGB: the display values, tagged sRGB where the format can say so;\n"
                     "  linear: their sRGB decoding.\n";
  if (!w.oiio) help += "  (no other: " + w.moduleError + ")\n";
  return help;
}

std::uint64_t ppmFileSize(int width, int height, const std::filesystem::path& path,
                          const ImageOptions& options) {
  if (!isPpm(path)) return 0;
  int bits = storedBits(ppmFormat(), options);
  return ppmHeader(width, height, bits).size() + std::uint64_t{3} * (bits == 16 ? 2 : 1) *
                                                     static_cast<std::uint64_t>(width) *
                                                     static_cast<std::uint64_t>(height);
}

std::string ppmImageBytes(const render::Image& image, const ImageOptions& options) {
  return ppmBytes(image, storedBits(ppmFormat(), options));
}

namespace {

// writeImageFile's steps; a failure's message is the reason alone.
tools::MaybeFailure writeImageBytes(const render::Image& image, const std::filesystem::path& path,
                                    const ImageOptions& options, bool replace) {
  if (options.alpha &&
      image.coverage.size() != static_cast<std::size_t>(image.width) * image.height) {
    return cannotWrite("the render has no coverage for --alpha");
  }
  std::optional<ImageFormat> own = ownFormat(path);
  Writable w;
  if (!own) w = writableFormats();
  const ImageFormat* format = own ? &*own : findImageFormat(w.formats, path);
  if (!format) {
    return cannotWrite(w.oiio
                           ? "no image format for the extension '" + path.extension().string() + "'"
                           : w.moduleError);
  }
  if (std::optional<std::string> refusal =
          imageOptionsRefusal(own ? std::vector<ImageFormat>{*own} : w.formats, *format, options)) {
    return cannotWrite(*refusal);
  }
  int bits = storedBits(*format, options);
  // The file's bytes are made first, in memory, and only then is the
  // temporary beside the target opened, written by checked writes, flushed
  // and renamed (file_io.h): no writer's failure, unreported short write or
  // exit() can leave a temporary or a part of an image behind.
  std::string ownBytes;
  MemoryFile encoded;
  std::string_view bytes;
  if (own) {
    if (isPng(path)) {
      tools::Outcome<std::string> png = pngBytes(image, options, bits);
      if (!png) return png.failure();
      ownBytes = std::move(*png);
    } else {
      ownBytes = ppmBytes(image, bits);
    }
    bytes = ownBytes;
  } else {
    if (tools::MaybeFailure failure =
            writeThroughOiio(*w.oiio, image, *format, options, path, encoded)) {
      return failure;
    }
    tools::Outcome<std::string_view> written = encoded.bytes();
    if (!written) return written.failure();
    if (written->empty()) {
      return cannotWrite("OpenImageIO's " + format->name + " writer wrote nothing");
    }
    bytes = *written;
  }
  tools::StagedFile file;
  tools::MaybeFailure failure = file.open(path, false);
  if (!failure) failure = file.write(bytes);
  if (!failure) failure = file.commit(replace);
  return failure;
}

}  // namespace

tools::MaybeFailure writeImageFile(const render::Image& image, const std::filesystem::path& path,
                                   const ImageOptions& options, bool replace) {
  tools::MaybeFailure failure = writeImageBytes(image, path, options, replace);
  if (!failure) return std::nullopt;
  return tools::fileFailure(failure->code, path.string(),
                            "cannot write the image: " + failure->message);
}

tools::Outcome<ImageRegionFile> readImageRegion(const std::filesystem::path& path,
                                                std::int64_t maxPixels) {
  std::string error;
  std::optional<OiioModule> oiio = loadOiio(error);
  if (!oiio) return tools::toolFailure(tools::ExitCode::InvalidInput, error);
  return readImageRegionWith(oiio->read, path, maxPixels);
}

tools::Outcome<ImageRegionFile> readImageRegionWith(SfrenderOiioRead read,
                                                    const std::filesystem::path& path,
                                                    std::int64_t maxPixels) {
  std::string name = "'" + path.string() + "'";
  auto cannotRead = [&](const std::string& why) {
    return tools::toolFailure(tools::ExitCode::IoError, "cannot read " + name + ": " + why);
  };
  auto cannotMerge = [&](const std::string& what) {
    return tools::toolFailure(tools::ExitCode::InvalidInput, name + what);
  };
  // Before OpenImageIO opens it: /dev/zero would be read for ever, a pipe
  // block.
  if (tools::MaybeFailure problem = tools::regularFileProblem(path)) {
    return cannotRead(problem->message);
  }
  // OpenEXR allocates what an attribute declares (exr_header.h).
  tools::Outcome<std::string> head = tools::readWholeFile(path, kExrHeaderBytes);
  std::error_code failed;
  std::uintmax_t size = std::filesystem::file_size(path, failed);
  if (!head || failed) {
    return cannotRead(head ? failed.message() : head.failure().message);
  }
  if (std::optional<std::string> problem = exrHeaderProblem(*head, size)) {
    return cannotMerge(*problem);
  }
  ImageRegionFile file;
  char message[512] = "";
  int status = read(path.c_str(), &file.region, nullptr, 0, message, sizeof message);
  if (status < 0) {
    return cannotMerge(std::string(" is not an OpenEXR file; ") + kRegionsAreFloatExr);
  }
  if (status == 0) return cannotRead(message);
  if (std::optional<std::string> refusal = regionRefusal(file.region, maxPixels)) {
    return cannotMerge(*refusal);
  }
  const SfrenderImageRegion checked = file.region;
  file.rgb.assign(std::size_t{3} * static_cast<std::size_t>(checked.width) * checked.height, 0.0f);
  if (read(path.c_str(), &file.region, file.rgb.data(), file.rgb.size(), message, sizeof message) !=
      1) {
    return cannotRead(message);
  }
  // The pixels are read by a second opening: what was checked must be what
  // was read, were the file replaced in between.
  if (std::memcmp(&checked, &file.region, sizeof checked) != 0) {
    return cannotRead("it changed while it was read");
  }
  if (std::optional<std::string> value = nonFiniteValue(file)) {
    return cannotMerge(" holds " + *value + "; a render writes finite values only");
  }
  return file;
}

}  // namespace image
