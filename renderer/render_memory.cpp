#include "renderer/render_memory.h"

#include <sys/resource.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "renderer/image.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "renderer/saturating.h"

namespace render {

namespace {

// Bytes in words a reader takes in at a glance: MiB from 1 MiB up.
std::string amount(std::uint64_t bytes) {
  if (bytes < (1u << 20)) return std::to_string(bytes) + " bytes";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1 << 20));
  return text;
}

}  // namespace

std::uint64_t RenderMemoryEstimate::total() const {
  return saturatingSum(saturatingSum(image, scene), bvh);
}

RenderSize renderSizeOf(const scene::Scene& scene, const RenderSettings& settings) {
  return {.objects = scene.objects.size(),
          .lights = scene.lights.size(),
          .materials = scene.objects.size(),
          .width = settings.width,
          .height = settings.height,
          .cameraSamples = uniformSampleCount(settings),
          .coverage = settings.coverage};
}

RenderMemoryEstimate estimateRenderMemory(const RenderSize& size) {
  RenderMemoryEstimate e;
  // The float image (with its coverage); the writer's copy of it in the
  // file's values (one or two bytes a channel, or EXR's linear floats); and
  // the file itself, made whole in memory before it is written (at most as
  // large as that copy). An EXR measured 2.8 times the float image at peak.
  e.image = saturatingProduct(Image::bytesFor(size.width, size.height, size.coverage), 3);
  RenderScene::Bytes compiled =
      RenderScene::bytesFor(size.objects, size.lights, size.materials, size.cameraSamples);
  e.scene = compiled.scene;
  e.bvh = compiled.bvh;
  return e;
}

std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo) {
  return parseKibibyteField(meminfo, "MemAvailable:");
}

namespace {

std::optional<std::string> readText(const char* path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<std::uint64_t> parseNumber(std::string_view text) {
  std::uint64_t n = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end == text.data()) return std::nullopt;
  return n;
}

}  // namespace

std::optional<std::uint64_t> parseKibibyteField(std::string_view text, std::string_view key) {
  std::size_t at = text.find(key);
  while (at != std::string_view::npos && at > 0 && text[at - 1] != '\n') {
    at = text.find(key, at + 1);
  }
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view rest = text.substr(at + key.size());
  std::size_t digits = rest.find_first_not_of(" \t");
  if (digits == std::string_view::npos) return std::nullopt;
  rest.remove_prefix(digits);
  std::uint64_t kib = 0;
  auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), kib);
  if (ec != std::errc() || end == rest.data()) return std::nullopt;
  // The kernel writes "kB" and means KiB.
  std::string_view unit = rest.substr(static_cast<std::size_t>(end - rest.data()));
  if (!unit.starts_with(" kB")) return std::nullopt;
  return saturatingProduct(kib, 1024);
}

std::optional<std::uint64_t> addressSpaceLeft(std::optional<std::uint64_t> limit,
                                              std::string_view status) {
  if (!limit) return std::nullopt;
  std::uint64_t used = parseKibibyteField(status, "VmSize:").value_or(0);
  return used >= *limit ? 0 : *limit - used;
}

std::optional<std::uint64_t> cgroupMemoryLeft(std::string_view max, std::string_view current) {
  std::optional<std::uint64_t> limit = parseNumber(max);  // "max\n": no limit
  if (!limit) return std::nullopt;
  std::uint64_t used = parseNumber(current).value_or(0);
  return used >= *limit ? 0 : *limit - used;
}

std::optional<std::string> cgroupFolder(std::string_view procSelfCgroup) {
  for (std::size_t start = 0; start < procSelfCgroup.size();) {
    std::size_t end = procSelfCgroup.find('\n', start);
    if (end == std::string_view::npos) end = procSelfCgroup.size();
    std::string_view line = procSelfCgroup.substr(start, end - start);
    if (line.starts_with("0::/")) return "/sys/fs/cgroup" + std::string(line.substr(3));
    start = end + 1;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> leastOf(std::initializer_list<std::optional<std::uint64_t>> limits) {
  std::optional<std::uint64_t> least;
  for (const std::optional<std::uint64_t>& limit : limits) {
    if (limit && (!least || *limit < *least)) least = limit;
  }
  return least;
}

std::optional<std::uint64_t> readAvailableMemory() {
  std::optional<std::uint64_t> free;
  if (std::optional<std::string> meminfo = readText("/proc/meminfo")) {
    free = parseMemAvailable(*meminfo);
  }
  // An address-space limit (ulimit -v) counts every mapping, not only what
  // is touched: an allocation past it fails however much memory is free.
  std::optional<std::uint64_t> addressSpace;
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    addressSpace = addressSpaceLeft(static_cast<std::uint64_t>(limit.rlim_cur),
                                    readText("/proc/self/status").value_or(""));
  }
  // A container's memory.max: past it the kernel kills the process, which
  // no exception reports. The process's own cgroup first (without a cgroup
  // namespace it is not the root's), then the root of the mount.
  std::optional<std::uint64_t> cgroup;
  std::optional<std::string> folder = cgroupFolder(readText("/proc/self/cgroup").value_or(""));
  for (const std::string& base :
       {folder.value_or("/sys/fs/cgroup"), std::string("/sys/fs/cgroup")}) {
    std::optional<std::string> max = readText((base + "/memory.max").c_str());
    if (!max) continue;
    cgroup = cgroupMemoryLeft(*max, readText((base + "/memory.current").c_str()).value_or(""));
    break;
  }
  return leastOf({free, addressSpace, cgroup});
}

std::optional<std::string> renderMemoryRefusal(const RenderMemoryEstimate& estimate,
                                               std::optional<std::uint64_t> available) {
  if (!available || estimate.total() <= *available) return std::nullopt;
  return "the render needs about " + amount(estimate.total()) + " (image " +
         amount(estimate.image) + ", scene " + amount(estimate.scene) + ", BVH " +
         amount(estimate.bvh) + ") but only " + amount(*available) +
         " of memory is available (the least of the free memory, what the address-space "
         "limit leaves and what the cgroup's memory.max leaves)";
}

}  // namespace render
