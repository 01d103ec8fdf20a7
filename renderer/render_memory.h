// What a render will allocate, against the memory the machine has free: a
// render that cannot fit is refused before it starts rather than killed
// (or swapping) half-way. The estimate is made here, beside the code that
// allocates, from that code's own sizes (Image::bytesFor,
// RenderScene::bytesFor, Bvh::bytesFor), so that it follows the renderer
// when its types change.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace scene {
struct Scene;
}  // namespace scene

namespace render {

struct RenderSettings;

/// Bytes still to be allocated once the scene has been read: the compiled
/// scene (objects, lights), the BVH with its build temporaries, the image,
/// its copy in the file's values and the file's bytes. An estimate from the
/// types' sizes, not a measure.
struct RenderMemoryEstimate {
  std::uint64_t image = 0;  ///< the float image, its copy for the file, the file
  std::uint64_t scene = 0;  ///< RenderScene::Bytes::scene
  std::uint64_t bvh = 0;    ///< RenderScene::Bytes::bvh

  /// The sum. Saturates: a hostile size gives a huge total, never a wrapped
  /// small one.
  std::uint64_t total() const;
};

/// What a render's memory depends on.
struct RenderSize {
  std::uint64_t objects = 0;
  std::uint64_t lights = 0;
  /// The distinct materials, colour aside (RenderSceneBuilder numbers
  /// them): the count known, or a bound such as `objects`.
  std::uint64_t materials = 1;
  int width = 0;
  int height = 0;
  /// The camera samples (uniformSampleCount), which decide whether the
  /// lights' direction grids are built (RenderScene::lightGridsPay).
  std::uint64_t cameraSamples = 0;
  bool coverage = false;
};

/// The size of rendering `scene`, read whole, with `settings`: its materials
/// bounded by its objects, the camera samples and coverage the settings'.
RenderSize renderSizeOf(const scene::Scene& scene, const RenderSettings& settings);

/// The estimate for rendering a scene of `size` into its image, with its
/// coverage or not, and writing it to a file.
RenderMemoryEstimate estimateRenderMemory(const RenderSize& size);

/// MemAvailable of /proc/meminfo's text, in bytes, or nothing when absent.
std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo);

/// The kB figure of a /proc line such as /proc/self/status's "VmSize:", in
/// bytes, or nothing when absent.
std::optional<std::uint64_t> parseKibibyteField(std::string_view text, std::string_view key);

/// What RLIMIT_AS leaves to allocate: the limit less the address space in use
/// (VmSize of /proc/self/status), or nothing when there is no limit.
std::optional<std::uint64_t> addressSpaceLeft(std::optional<std::uint64_t> limit,
                                              std::string_view status);

/// What a cgroup v2 leaves: memory.max less memory.current (their texts), or
/// nothing for "max" or what cannot be read.
std::optional<std::uint64_t> cgroupMemoryLeft(std::string_view max, std::string_view current);

/// The cgroup v2 folder of the process, from /proc/self/cgroup's text
/// ("0::/PATH"): /sys/fs/cgroup/PATH, or nothing without a v2 line.
std::optional<std::string> cgroupFolder(std::string_view procSelfCgroup);

/// The least of those that are known; nothing when none is.
std::optional<std::uint64_t> leastOf(std::initializer_list<std::optional<std::uint64_t>> limits);

/// Where the free memory comes from: readAvailableMemory on the machine,
/// anything a test likes in a test.
using AvailableMemoryProbe = std::function<std::optional<std::uint64_t>()>;

/// The least of MemAvailable (/proc/meminfo), what RLIMIT_AS leaves
/// (getrlimit, ulimit -v, prlimit --as) and what the cgroup's memory.max
/// leaves (cgroup v2, the process's own cgroup, else
/// /sys/fs/cgroup/memory.max); nothing when none can be read.
std::optional<std::uint64_t> readAvailableMemory();

/// Why the render does not fit, with the estimate and the free memory in
/// the words, or nothing when it fits or the free memory is unknown.
std::optional<std::string> renderMemoryRefusal(const RenderMemoryEstimate& estimate,
                                               std::optional<std::uint64_t> available);

}  // namespace render
