#include "image/region_merge.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "image/image_file.h"

namespace image {

namespace {

float floatOfBits(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::uint32_t bitsOfFloat(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// The smallest non-negative finite float whose decoding is at least
// `linear` (> 0), by bisection over the bit patterns, which order
// non-negative floats as their values: srgbToLinear does not decrease.
float bisectDisplay(float linear) {
  std::uint32_t low = 0, high = bitsOfFloat(std::numeric_limits<float>::max());
  while (low < high) {
    std::uint32_t middle = low + (high - low) / 2;
    if (srgbToLinear(floatOfBits(middle)) >= linear) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return floatOfBits(low);
}

// Files that do not make one image.
tools::ToolFailure invalidRegions(std::string message) {
  return tools::toolFailure(tools::ExitCode::InvalidInput, std::move(message));
}

std::string windowText(int x, int y, int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height) + " at " + std::to_string(x) + "," +
         std::to_string(y);
}

// Copies one file's pixels into `whole`, counting what each pixel got in
// `filled`; a failure when a pixel it overlaps disagrees.
tools::MaybeFailure placeRegion(const ImageRegionFile& file, const std::string& name,
                                render::Image& whole, std::vector<float>& linear,
                                std::vector<unsigned char>& filled) {
  const SfrenderImageRegion& r = file.region;
  for (int row = 0; row < r.height; ++row) {
    for (int column = 0; column < r.width; ++column) {
      std::size_t to = static_cast<std::size_t>(r.y - r.fullY + row) * whole.width +
                       static_cast<std::size_t>(r.x - r.fullX + column);
      const float* from = &file.rgb[3 * (static_cast<std::size_t>(row) * r.width + column)];
      if (filled[to] && std::memcmp(&linear[3 * to], from, 3 * sizeof(float)) != 0) {
        return invalidRegions(name + " and an earlier region differ at pixel " +
                              std::to_string(r.x - r.fullX + column) + "," +
                              std::to_string(r.y - r.fullY + row));
      }
      std::memcpy(&linear[3 * to], from, 3 * sizeof(float));
      filled[to] = 1;
    }
  }
  return std::nullopt;
}

}  // namespace

float displayFromLinear(float linear) {
  if (std::isnan(linear)) return 0.0f;
  if (linear < 0.0f) return -displayFromLinear(-linear);
  if (linear == 0.0f) return 0.0f;
  // The inverse of the decoding in double, then to the exact float by a few
  // steps: the first float whose decoding reaches `linear`.
  double l = std::min(static_cast<double>(linear), 1e30);
  float d = static_cast<float>(l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055);
  constexpr float kLargest = std::numeric_limits<float>::max();
  for (int step = 0; step < 16 && srgbToLinear(d) < linear; ++step) d = std::nextafter(d, kLargest);
  for (int step = 0; step < 16 && d > 0.0f && srgbToLinear(std::nextafter(d, 0.0f)) >= linear;
       ++step) {
    d = std::nextafter(d, 0.0f);
  }
  bool first =
      srgbToLinear(d) >= linear && (d == 0.0f || srgbToLinear(std::nextafter(d, 0.0f)) < linear);
  return first ? d : bisectDisplay(linear);
}

tools::Outcome<render::Image> mergeImageRegions(const std::vector<std::filesystem::path>& files,
                                                std::int64_t maxPixels) {
  if (files.empty()) return invalidRegions("no regions to merge");
  render::Image whole;
  std::vector<float> linear;
  std::vector<unsigned char> filled;
  SfrenderImageRegion display{};
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::filesystem::path& path = files[i];
    std::string name = "'" + path.string() + "'";
    tools::Outcome<ImageRegionFile> read = readImageRegion(path, maxPixels);
    if (!read) return read.failure();
    const ImageRegionFile& file = *read;
    const SfrenderImageRegion& r = file.region;
    if (!r.floating || r.bits != 32) {
      return invalidRegions(name + " holds " + std::to_string(r.bits) + "-bit " +
                            (r.floating ? "floating-point" : "integer") + " values; " +
                            kRegionsAreFloatExr);
    }
    // By place, not by name: a file named twice is two regions, which
    // agree where they overlap.
    if (i == 0) {
      display = r;
      whole.width = r.fullWidth;
      whole.height = r.fullHeight;
      std::size_t pixels = static_cast<std::size_t>(whole.width) * whole.height;
      linear.assign(3 * pixels, 0.0f);
      filled.assign(pixels, 0);
    } else if (r.fullX != display.fullX || r.fullY != display.fullY ||
               r.fullWidth != display.fullWidth || r.fullHeight != display.fullHeight) {
      return invalidRegions(
          name + " is a region of a " + windowText(r.fullX, r.fullY, r.fullWidth, r.fullHeight) +
          " image, '" + files.front().string() + "' of a " +
          windowText(display.fullX, display.fullY, display.fullWidth, display.fullHeight) + " one");
    }
    if (tools::MaybeFailure failure = placeRegion(file, name, whole, linear, filled)) {
      return *failure;
    }
  }
  for (std::size_t p = 0; p < filled.size(); ++p) {
    if (filled[p]) continue;
    return invalidRegions("no region holds pixel " + std::to_string(p % whole.width) + "," +
                          std::to_string(p / whole.width) + " of the " +
                          std::to_string(whole.width) + "x" + std::to_string(whole.height) +
                          " image");
  }
  whole.fullWidth = whole.width;
  whole.fullHeight = whole.height;
  whole.rgb.resize(linear.size());
  for (std::size_t i = 0; i < linear.size(); ++i) whole.rgb[i] = displayFromLinear(linear[i]);
  return whole;
}

}  // namespace image
