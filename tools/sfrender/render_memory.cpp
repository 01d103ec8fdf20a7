#include "tools/sfrender/render_memory.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "renderer/bounds.h"
#include "renderer/bvh.h"
#include "renderer/render_scene.h"

namespace tools {

namespace {

// Saturating arithmetic: a hostile size must give a huge estimate, never a
// wrapped small one.
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}

std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

// Bytes in words a reader takes in at a glance: MiB from 1 MiB up.
std::string amount(std::uint64_t bytes) {
  if (bytes < (1u << 20)) return std::to_string(bytes) + " bytes";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1 << 20));
  return text;
}

}  // namespace

std::uint64_t RenderMemoryEstimate::total() const {
  return plus(plus(image, scene), bvh);
}

RenderMemoryEstimate estimateRenderMemory(std::uint64_t objects, std::uint64_t lights, int width,
                                          int height) {
  RenderMemoryEstimate e;
  std::uint64_t pixels = times(static_cast<std::uint64_t>(width > 0 ? width : 0),
                               static_cast<std::uint64_t>(height > 0 ? height : 0));
  // Three floats a pixel, and for the file one byte a channel (PPM, PNG),
  // or the floats again where OpenImageIO copies them (EXR, TIFF): the larger.
  e.image = times(pixels, 3 * sizeof(float) + 3 * sizeof(float));
  // Each object once compiled, and its index in the bounded or plane list.
  e.scene = plus(times(objects, sizeof(render::RenderObject) + sizeof(std::uint32_t)),
                 times(lights, sizeof(render::RenderLight)));
  // The build: a box per object (in a vector that grows by doubling), its
  // centre, then up to two nodes and one item per object.
  e.bvh = times(objects, 2 * sizeof(render::Bounds) + sizeof(glm::dvec3) +
                             2 * sizeof(render::BvhNode) + sizeof(std::uint32_t));
  return e;
}

std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo) {
  constexpr std::string_view kKey = "MemAvailable:";
  std::size_t at = meminfo.find(kKey);
  if (at == std::string_view::npos || (at > 0 && meminfo[at - 1] != '\n')) return std::nullopt;
  std::string_view rest = meminfo.substr(at + kKey.size());
  std::size_t digits = rest.find_first_not_of(' ');
  if (digits == std::string_view::npos) return std::nullopt;
  rest.remove_prefix(digits);
  std::uint64_t kib = 0;
  auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), kib);
  if (ec != std::errc() || end == rest.data()) return std::nullopt;
  // The kernel writes "kB" and means KiB.
  std::string_view unit = rest.substr(static_cast<std::size_t>(end - rest.data()));
  if (!unit.starts_with(" kB")) return std::nullopt;
  return times(kib, 1024);
}

std::optional<std::uint64_t> readAvailableMemory() {
  std::ifstream in("/proc/meminfo");
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return parseMemAvailable(text.str());
}

std::optional<std::string> renderMemoryRefusal(const RenderMemoryEstimate& estimate,
                                               std::optional<std::uint64_t> available) {
  if (!available || estimate.total() <= *available) return std::nullopt;
  return "the render needs about " + amount(estimate.total()) + " (image " +
         amount(estimate.image) + ", scene " + amount(estimate.scene) + ", BVH " +
         amount(estimate.bvh) + ") but only " + amount(*available) + " of memory is available";
}

}  // namespace tools
