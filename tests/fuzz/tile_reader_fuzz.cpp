// libFuzzer target: the reader of sfrender --merge's tiles (readImageRegionWith,
// image/image_file.h) on any bytes. The bytes are written to a file
// named .exr, as a tile on disk, since OpenImageIO reads by name (its EXR
// reader first, by the extension, then any other whose format the bytes
// have). OpenImageIO's module (oiio_module.cpp), which sfrender loads at run
// time, is compiled into the target instead, so that its code is
// instrumented too; the reader is handed its read function. A tile it
// accepts holds only finite values, as many as its data window, within the
// pixel limit, and each gives a finite display value; a refusal carries an
// error.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "image/image_file.h"
#include "image/oiio_module.h"
#include "image/region_merge.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int sfrender_oiio_read(const char* path, SfrenderImageRegion* region, float* pixels,
                                  std::size_t capacity, char* error, std::size_t errorSize);

namespace {

// Small, so that an input cannot make the target slow: the bound is what
// is tested, not its size (sfrender's is --max-pixels).
constexpr std::int64_t kMaxPixels = std::int64_t{1} << 16;

// The tile's file: one a process, in a folder of the target's own.
std::filesystem::path tileFile() {
  std::error_code ignored;
  std::filesystem::path folder =
      std::filesystem::temp_directory_path(ignored) / "scenefile-fuzz-tiles";
  std::filesystem::create_directories(folder, ignored);
  return folder / ("tile-" + std::to_string(::getpid()) + ".exr");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = tileFile();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  tools::Outcome<image::ImageRegionFile> read =
      image::readImageRegionWith(sfrender_oiio_read, file, kMaxPixels);
  if (!read) {
    if (read.failure().message.empty()) fuzz::propertyFailed("a refused tile carries no error", "");
    return 0;
  }
  const image::ImageRegionFile& tile = *read;
  const SfrenderImageRegion& r = tile.region;
  std::int64_t pixels = std::int64_t{r.width} * r.height;
  if (r.width <= 0 || r.height <= 0 || pixels > kMaxPixels ||
      std::int64_t{r.fullWidth} * r.fullHeight > kMaxPixels ||
      tile.rgb.size() != static_cast<std::size_t>(3 * pixels)) {
    fuzz::propertyFailed("an accepted tile is not bounded by the pixel limit",
                         std::to_string(r.width) + "x" + std::to_string(r.height) + " of " +
                             std::to_string(r.fullWidth) + "x" + std::to_string(r.fullHeight));
  }
  for (float value : tile.rgb) {
    if (!std::isfinite(value) || !std::isfinite(image::displayFromLinear(value))) {
      fuzz::propertyFailed("an accepted tile holds a value that is not finite",
                           std::to_string(value));
    }
  }
  return 0;
}
