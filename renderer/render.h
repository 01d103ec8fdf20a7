// Rendering a whole image: the camera of RENDERING.md, stratified samples
// with a seed, tiles spread over threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "renderer/render_scene.h"
#include "renderer/tracer.h"

namespace render {

struct RenderSettings {
  int width = 640;
  int height = 480;
  double verticalFovDegrees = 60.0;
  int samplesPerPixel = 1;
  int maxDepth = 5;
  // The most adaptive depth control may lower a channel of a sample (and so
  // of a pixel) by leaving out reflected and refracted rays: half a level of
  // an 8-bit image. A pixel whose level that could change is traced again
  // (RenderStatistics::retracedPixels), so every level is what full tracing
  // gives (docs/RENDERING.md,
  // "Cost"). 0 traces every branch to the depth limit.
  double pruneTolerance = 0.5 / 255.0;
  // The most reflected and refracted rays one sample traces, whatever the
  // scene: where every hit passes on nearly all it receives to both its
  // children, no tolerance bounds the work, and this does (docs/RENDERING.md,
  // "Cost"). 0: no limit, and then no pixel is retraced, so that an 8-bit
  // level can come out one below what full tracing gives.
  std::uint64_t maxRaysPerSample = 4096;
  // The largest level of the integer image the render will be stored in:
  // what retracing keeps to the level of full tracing (255 for 8 bits,
  // 65535 for 16, with pruneTolerance half of one of its levels).
  double levels = 255.0;
  // Whether the image gets Image::coverage, for an image with alpha.
  bool coverage = false;
  int threads = 0;  // 0: every core
  std::uint64_t seed = 0;
};

// Primary rays of the scene's camera: a pinhole at the eye, forward and up
// orthonormalised (forward first), the vertical field of view given and the
// horizontal one from the aspect ratio.
class PinholeCamera {
 public:
  PinholeCamera(const scene::Camera& camera, const RenderSettings& settings);
  // The ray through image position (x, y), in pixels from the top-left
  // corner: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
  Ray rayThrough(double x, double y) const;
  const glm::dvec3& eye() const { return eye_; }

 private:
  glm::dvec3 eye_, forward_, up_, right_;
  double tanHalfHeight_;
  double tanHalfWidth_;
  double width_, height_;
};

// The colours RENDERING.md computes, row by row from the top, three floats
// a pixel; and, when asked for, each pixel's coverage.
struct Image {
  /// Floats a pixel in `rgb`: red, green, blue.
  static constexpr std::size_t kChannels = 3;

  /// The pixels held: the region's size (RenderSettings::region).
  int width = 0;
  int height = 0;
  /// Where the region's top-left pixel lies in the full image, and the full
  /// image's size (its display window); 0, 0 and width x height for a full
  /// render.
  int originX = 0, originY = 0, fullWidth = 0, fullHeight = 0;
  std::vector<float> rgb;
  /// With RenderSettings::coverage, one float a pixel: the fraction of its
  /// samples whose camera ray meets an object (0 where only the background
  /// shows, 1 where every sample hits); empty otherwise. The background is
  /// black, so `rgb` is already that coverage times the mean colour of the
  /// samples that hit: premultiplied.
  std::vector<float> coverage;
  glm::vec3 pixel(int x, int y) const {
    const float* p = &rgb[kChannels * (static_cast<std::size_t>(y) * width + x)];
    return {p[0], p[1], p[2]};
  }

  /// The bytes of `rgb`, and of `coverage` when `withCoverage`, for an
  /// image of `width` x `height` pixels, as renderImage allocates them; a
  /// side below 1 counts as 0. Saturates.
  static std::uint64_t bytesFor(int width, int height, bool withCoverage = false);
};

struct RenderStatistics {
  double seconds = 0.0;
  RayCounts rays;
  // Pixels traced again, with a 64th of the tolerance and then in full,
  // because what adaptive depth control left out could have moved their
  // 8-bit level (their primary rays count again).
  std::uint64_t retracedPixels = 0;
};

// Called after each finished tile with the tiles done and the total.
using ProgressCallback = std::function<void(int done, int total)>;

// Asks a render to stop before it is done: set from any thread, or from a
// signal handler (the atomic is lock-free), and read by the render before
// each row of pixels, so that a render stops within a row's time whatever
// the image's size (the Python module's Ctrl+C). Once set it stays set.
class CancelFlag {
 public:
  void request() noexcept { requested_.store(true, std::memory_order_relaxed); }
  bool requested() const noexcept { return requested_.load(std::memory_order_relaxed); }

 private:
  static_assert(std::atomic<bool>::is_always_lock_free);
  std::atomic<bool> requested_{false};
};

// What renderImage throws when its CancelFlag is set: there is no image,
// since a part of one would look finished where it is not.
class RenderCancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "the render was cancelled"; }
};

// The image of `scene`. With `cancel`, stops once it is requested: every
// thread leaves its row, and RenderCancelled is thrown when all are joined.
Image renderImage(const RenderScene& scene, const RenderSettings& settings,
                  RenderStatistics* statistics = nullptr, const ProgressCallback& progress = {},
                  const CancelFlag* cancel = nullptr);

// The index of the object each pixel's centre ray meets first, or -1: the
// picture that geometry tests compare.
std::vector<std::int32_t> renderObjectIds(const RenderScene& scene, const RenderSettings& settings);

// The position of sample `index` of `count` in pixel (i, j): the centre for
// one sample, else a jittered point in its own cell of a stratified grid,
// the same for a given seed whatever the thread.
glm::dvec2 samplePosition(int i, int j, int index, int count, std::uint64_t seed);

}  // namespace render
