// Rendering a whole image: the camera of RENDERING.md, stratified samples
// with a seed, tiles spread over threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/render_scene.h"
#include "renderer/tracer.h"

namespace render {

// A rectangle of pixels of the full image, half-open: columns x0 to x1 - 1,
// rows y0 to y1 - 1.
struct PixelRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return empty() ? 0 : x1 - x0; }
  int height() const { return empty() ? 0 : y1 - y0; }
};

// The side, in pixels, of the square tiles that a render hands out to its
// threads (the last in a row or column cut at the region's edge).
inline constexpr int kRenderTileSize = 32;

// Tile `index` (0-based) of `count` of a `width` x `height` image: the
// index-th of `count` horizontal bands of whole rows, from the top, their
// heights differing by at most 1 (the taller first). Empty where the index
// is out of range or there are more bands than rows.
PixelRegion imageTile(int width, int height, int index, int count);

// Where renderImage traces (docs/RENDERING.md, "The GPU path").
enum class RenderDevice {
  Cpu,
  // A Vulkan device with shaderFloat64 and shaderInt64 (lavapipe, a CPU
  // implementation, counts too): the same picture to within rounding.
  Gpu,
  // The GPU when a real one (not a CPU implementation) is present, the
  // render uniform, and it has at least kAutoGpuMinSamplesPerThread camera
  // samples for each thread the CPU would render with; the CPU otherwise.
  Auto,
};

// Auto's threshold: a GPU render first pays a fixed start (instance, device,
// the pipeline's compilation, the scene's upload, the readback: about 0.25 s
// on an NVIDIA H200, whatever the samples), while the CPU's time grows with
// the samples each thread traces. There the GPU came out ahead from half a
// million to a million samples a thread against 2 threads and from one to
// two million against 16 (docs/PERFORMANCE.md, "GPU (Vulkan)").
inline constexpr std::uint64_t kAutoGpuMinSamplesPerThread = 1'000'000;

namespace gpu {
class VulkanContext;
}

// A Vulkan device opened once for many GPU renders (RenderSettings::gpu),
// the first that fits as the GPU path takes it (a real GPU before a CPU
// implementation). Renders through it skip the device's start (0.16 s on
// an NVIDIA H200), and the driver stays loaded between them: a render that
// opens its own device loads the driver and unloads it after, and NVIDIA's
// (580) keeps some of the process's static TLS each time, so that after
// about 30 loads in one process no instance can be made (docs/RENDERING.md,
// "The GPU path"). One render at a time goes through it.
class GpuDevice {
 public:
  // Throws DeviceUnavailable where no device fits or the build has no
  // Vulkan.
  GpuDevice();
  ~GpuDevice();
  GpuDevice(const GpuDevice&) = delete;
  GpuDevice& operator=(const GpuDevice&) = delete;

  const std::string& name() const;
  // A CPU implementation such as lavapipe.
  bool isCpu() const;
  // What the GPU path renders with (renderer/gpu).
  const gpu::VulkanContext& vulkan() const;

 private:
  struct Device;
  std::unique_ptr<Device> device_;
};

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
  // Whether camera rays find their hits as packets (RenderScene::closestHits,
  // docs/RENDERING.md, "Packets"): the same image, bit for bit, either way;
  // false traces each alone, for the tests and benchmarks that compare.
  bool packets = true;
  // Whether camera rays find their hits through the eye's direction grid
  // (RenderScene::closestHitsFromEye, docs/RENDERING.md, "Direction
  // grids") where it can answer: the same image, bit for bit, either way.
  bool eyeGrid = true;
  int threads = 0;  // 0: every core
  std::uint64_t seed = 0;
  // Adaptive anti-aliasing (docs/RENDERING.md, "Adaptive sampling"): 0
  // samples every pixel samplesPerPixel times. Above 0, every pixel corner
  // is sampled, a pixel whose four corners agree is their mean, and a square
  // whose corners differ by more than this (in some channel, in the image's
  // units 0..1) or show different objects is cut in four, down to
  // subdivisionDepth(samplesPerPixel) cuts.
  double adaptiveThreshold = 0.0;
  // The part of the width x height image to render; empty: all of it. Its
  // pixels are exactly those of the full image's render (a region reaching
  // outside the image is cut to it).
  PixelRegion region;
  // On the GPU, adaptive anti-aliasing is refused, threads only pack the
  // scene for the upload, and the adaptive depth control's settings
  // (pruneTolerance, maxRaysPerSample) are not used: every branch is traced
  // to maxDepth.
  RenderDevice device = RenderDevice::Cpu;
  // The device GPU renders go through, kept open by the caller for as long
  // as renders use it; null: each GPU render opens a device of its own.
  // Auto with one given asks no probe: it takes it where it is a real GPU.
  const GpuDevice* gpu = nullptr;
};

// Why a render cannot run on the device asked for: no Vulkan device with
// doubles, a build without Vulkan, or a setting the GPU path does not do.
class DeviceUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether the GPU path can run here, and on what.
struct GpuProbe {
  bool available = false;
  bool isCpu = false;  // a CPU implementation such as lavapipe
  std::string name;
  std::string reason;  // why not, when not available
};
// Looks for a Vulkan device with shaderFloat64 and shaderInt64 (a real GPU
// first); with `allowCpu` false a CPU implementation does not count.
GpuProbe probeGpu(bool allowCpu = true);

// Whether a render with `settings` is one Auto gives a real GPU where one is
// present: uniform, with at least kAutoGpuMinSamplesPerThread camera samples
// for each thread of settings.threads.
bool autoPrefersGpu(const RenderSettings& settings);

// The device a render with `settings` runs on: Auto decided (autoPrefersGpu,
// then probing for a GPU), Cpu and Gpu as they are.
RenderDevice chooseDevice(const RenderSettings& settings);

// Primary rays of the scene's camera: a pinhole at the eye, forward and up
// orthonormalised (forward first), the vertical field of view given and the
// horizontal one from the aspect ratio.
class PinholeCamera {
 public:
  PinholeCamera(const scene::Camera& camera, const RenderSettings& settings);
  // The ray through image position (x, y), in pixels from the top-left
  // corner: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
  Ray rayThrough(double x, double y) const { return Ray{eye_, directionThrough(x, y)}; }
  // rayThrough's direction alone, inline: a packet's rays are filled member
  // by member, since a whole Ray copied from a temporary was loaded 16 bytes
  // at a time across the 8-byte stores that made it, and the loads waited.
  glm::dvec3 directionThrough(double x, double y) const {
    double sx = (2.0 * x / width_ - 1.0) * tanHalfWidth_;
    double sy = (1.0 - 2.0 * y / height_) * tanHalfHeight_;
    return glm::normalize(forward_ + sx * right_ + sy * up_);
  }
  const glm::dvec3& eye() const { return eye_; }
  // The rest of rayThrough's terms, for the GPU renderer.
  const glm::dvec3& forward() const { return forward_; }
  const glm::dvec3& up() const { return up_; }
  const glm::dvec3& right() const { return right_; }
  double tanHalfWidth() const { return tanHalfWidth_; }
  double tanHalfHeight() const { return tanHalfHeight_; }
  // The directions of the image as a window of a direction grid (the
  // camera's frame, the image's tangent extents), cut into columns x rows.
  GridWindow imageWindow(int columns, int rows) const;

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
  /// shows, 1 where every sample hits; with adaptive sampling, of the samples
  /// the pixel's colour is the mean of); empty otherwise. The background is
  /// black, so `rgb` is already that coverage times the mean colour of the
  /// samples that hit: premultiplied.
  std::vector<float> coverage;
  /// Pixel (x, y) of those held: (originX + x, originY + y) of the full image.
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
  // The pixels rendered, and the camera samples traced for them (retraces
  // aside; with adaptive sampling the pixel corners, (width + 1) x
  // (height + 1), and each lattice point a pixel traced, a point on the
  // side of two pixels of different tiles twice): samples / pixels is the
  // mean samples a pixel.
  std::uint64_t pixels = 0;
  std::uint64_t samples = 0;
  // Adaptive sampling: the pixels cut (whose corners differ), those of
  // them cut somewhere to the finest squares, and the pixels not cut that
  // took their centre too (whose corners differ by more than half the
  // threshold).
  std::uint64_t refinedPixels = 0;
  std::uint64_t fullySampledPixels = 0;
  std::uint64_t centredPixels = 0;
  // The GPU path's device (empty on the CPU), and the parts of `seconds`:
  // creating the device and compiling the pipeline, packing and uploading
  // the scene, the kernel (timestamp queries), and reading the image back.
  std::string device;
  double deviceStartSeconds = 0.0;
  double uploadSeconds = 0.0;
  double kernelSeconds = 0.0;
  double readbackSeconds = 0.0;
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

/// The pixels of the full image that `settings` asks for: its region cut to
/// the image, or all of it.
PixelRegion regionToRender(const RenderSettings& settings);

/// Whether a render with `settings` samples adaptively (docs/RENDERING.md,
/// "Adaptive sampling"): a threshold above 0 and more than one sample a
/// pixel to refine to.
bool samplesAdaptively(const RenderSettings& settings);

/// The camera samples a uniform render with `settings` takes: the pixels
/// of regionToRender times samplesPerPixel (at least 1).
std::uint64_t uniformSampleCount(const RenderSettings& settings);

/// An image of the pixels `settings` asks for (regionToRender), every
/// value 0, with its place in the full image, and coverage when asked for:
/// what each device's render fills in.
Image blankImageFor(const RenderSettings& settings);

// The image of `scene`. With `cancel`, stops once it is requested: every
// thread leaves its row, and RenderCancelled is thrown when all are joined.
Image renderImage(const RenderScene& scene, const RenderSettings& settings,
                  RenderStatistics* statistics = nullptr, const ProgressCallback& progress = {},
                  const CancelFlag* cancel = nullptr);

// The index of the object each pixel's centre ray meets first, or -1: the
// picture that geometry tests compare (of the whole image, whatever the
// region).
std::vector<std::int32_t> renderObjectIds(const RenderScene& scene, const RenderSettings& settings);

// The position of sample `index` of `count` in pixel (i, j): the centre for
// one sample, else a jittered point in its own cell of a stratified grid,
// the same for a given seed whatever the thread.
glm::dvec2 samplePosition(int i, int j, int index, int count, std::uint64_t seed);

}  // namespace render
