/// @file
/// Rendering a scene to an image, as the renderer tool does (docs/RENDERING.md): the
/// settings a user chooses, the progress and stop of a render, and the
/// image it gives.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <stop_token>
#include <vector>

#include "scenefile/scene.h"

namespace scene {

/// A rectangle of pixels of the full image, half-open: columns x0 to x1 - 1,
/// rows y0 to y1 - 1.
struct PixelRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return empty() ? 0 : x1 - x0; }
  int height() const { return empty() ? 0 : y1 - y0; }
};

/// Where a render traces (docs/RENDERING.md, "The GPU path").
enum class RenderDevice {
  Cpu,
  /// A Vulkan device with shaderFloat64 and shaderInt64 (lavapipe, a CPU
  /// implementation, counts too): the same picture to within rounding.
  /// Without one, or in a library built without Vulkan, the render throws
  /// std::runtime_error saying why.
  Gpu,
  /// The GPU when a real one (not a CPU implementation) is present, the
  /// render uniform, and it has enough camera samples for each thread the
  /// CPU would render with; the CPU otherwise.
  Auto,
};

/// What a render is asked for.
struct RenderSettings {
  int width = 640;   ///< in pixels
  int height = 480;  ///< in pixels
  /// The camera's vertical field of view, in degrees.
  double verticalFovDegrees = 60.0;
  int samplesPerPixel = 1;  ///< camera samples a pixel
  int maxDepth = 5;         ///< bounces of reflected and refracted rays
  /// Adaptive sampling (docs/RENDERING.md, "Adaptive sampling"): 0 samples every
  /// pixel samplesPerPixel times. Above 0, every pixel corner is sampled, a
  /// pixel whose four corners agree is their mean, and a square whose
  /// corners differ by more than this (in some channel, in the image's units
  /// 0..1) or show different objects is cut in four, down to as many cuts as
  /// samplesPerPixel allows.
  double adaptiveThreshold = 0.0;
  int threads = 0;         ///< 0: every core
  std::uint64_t seed = 0;  ///< of the sample positions
  /// The part of the width x height image to render; empty: all
  /// of it. Its pixels are exactly those of the full image's render (a
  /// region reaching outside the image is cut to it).
  PixelRegion region;
  /// On the GPU, adaptive sampling is refused, and every branch
  /// is traced to maxDepth.
  RenderDevice device = RenderDevice::Cpu;
  /// The image gets RenderedImage::coverage (for an alpha channel).
  bool coverage = false;
};

/// A rendered image: the display values RENDERING.md computes, row by row
/// from the top, three floats a pixel (sRGB-encoded, as an 8-bit image
/// stores them: eightBitLevels and linearValues convert them).
struct RenderedImage {
  /// Floats a pixel in `rgb`: red, green, blue.
  static constexpr std::size_t kChannels = 3;

  /// The pixels held: the region's size (RenderSettings::region).
  int width = 0;
  int height = 0;
  /// Where the region's top-left pixel lies in the full image, and the full
  /// image's size; 0, 0 and width x height for a full render.
  int originX = 0, originY = 0, fullWidth = 0, fullHeight = 0;
  std::vector<float> rgb;
  /// With RenderSettings::coverage, one float a pixel: the fraction of its
  /// samples whose camera ray meets an object; empty otherwise. The
  /// background is black, so `rgb` is already premultiplied by it.
  std::vector<float> coverage;
  /// Pixel (x, y) of those held: (originX + x, originY + y) of the full image.
  glm::vec3 pixel(int x, int y) const {
    const float* p = &rgb[kChannels * (static_cast<std::size_t>(y) * width + x)];
    return {p[0], p[1], p[2]};
  }

  /// The bytes of `rgb`, and of `coverage` when `withCoverage`, for an
  /// image of `width` x `height` pixels; a side below 1 counts as 0.
  /// Saturates.
  static std::uint64_t bytesFor(int width, int height, bool withCoverage = false);
};

/// Called after each finished tile with the tiles done and the total, on
/// one of the render's threads.
using RenderProgress = std::function<void(int done, int total)>;

/// How a caller follows a render and stops it.
struct RenderControl {
  RenderProgress progress;
  /// Once a stop is requested, the render stops within a row of pixels and
  /// throws RenderCancelled.
  std::stop_token stop;
};

/// What renderScene throws when it is stopped: there is no image, since a
/// part of one would look finished where it is not.
class RenderCancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "the render was cancelled"; }
};

/// The scene's own view (a POV-Ray or glTF camera's, Scene::view) in
/// `settings`, where the caller does not say otherwise: its field of view
/// unless `fovGiven`, and at its aspect ratio the side that `width` and
/// `height` leave open (the height, when neither is given). `settings`
/// holds the sizes and field of view to start from. What the tools do
/// before they render; a scene without a view leaves `settings` as it is.
void applySceneView(const Scene& scene, std::optional<int> width, std::optional<int> height,
                    bool fovGiven, RenderSettings& settings);

/// The image of `scene` (one that read without errors) with `settings`.
/// Throws RenderCancelled when stopped, std::bad_alloc when the image does
/// not fit in memory, std::runtime_error when the GPU asked for is missing.
RenderedImage renderScene(const Scene& scene, const RenderSettings& settings = {},
                          const RenderControl& control = {});

/// The 8-bit levels of `image.rgb`, as the tools write a PNG or PPM:
/// round(clamp(v, 0, 1) * 255), three bytes a pixel.
std::vector<std::uint8_t> eightBitLevels(const RenderedImage& image);

/// The linear values of `image.rgb`, as the tools write an EXR: sRGB's
/// decoding, extended past [0, 1] as in scRGB.
std::vector<float> linearValues(const RenderedImage& image);

}  // namespace scene
