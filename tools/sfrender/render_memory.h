// What a render will allocate, against the memory the machine has free: a
// render that cannot fit is refused before it starts rather than killed
// (or swapping) half-way.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace tools {

// Bytes still to be allocated once the scene has been read: the compiled
// scene (objects, lights), the BVH with its build temporaries, the image and
// its copy for the file. An estimate from the types' sizes, not a measure.
struct RenderMemoryEstimate {
  std::uint64_t image = 0;
  std::uint64_t scene = 0;
  std::uint64_t bvh = 0;

  // Saturates: a hostile size gives a huge total, never a wrapped small one.
  std::uint64_t total() const;
};

RenderMemoryEstimate estimateRenderMemory(std::uint64_t objects, std::uint64_t lights, int width,
                                          int height);

// MemAvailable of /proc/meminfo's text, in bytes, or nothing when absent.
std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo);

// Where the free memory comes from: /proc/meminfo on the machine, anything
// a test likes in a test.
using AvailableMemoryProbe = std::function<std::optional<std::uint64_t>()>;
std::optional<std::uint64_t> readAvailableMemory();

// Why the render does not fit, with the estimate and the free memory in
// the words, or nothing when it fits or the free memory is unknown.
std::optional<std::string> renderMemoryRefusal(const RenderMemoryEstimate& estimate,
                                               std::optional<std::uint64_t> available);

}  // namespace tools
