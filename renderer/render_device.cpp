// Which device renders: the Vulkan probe and the choice of `auto`
// (docs/RENDERING.md, "The GPU path").
#include <cstdint>

#include "renderer/parallel_parts.h"
#include "renderer/render.h"

#if SCENEFILE_VULKAN
#include "renderer/gpu/vulkan_context.h"
#endif

namespace render {

GpuProbe probeGpu(bool allowCpu) {
  GpuProbe probe;
#if SCENEFILE_VULKAN
  gpu::DeviceProbe found = gpu::VulkanContext::probe(allowCpu);
  probe.available = found.found;
  probe.isCpu = found.isCpu;
  probe.name = found.name;
  probe.reason = found.reason;
#else
  (void)allowCpu;
  probe.reason = "this build has no Vulkan (configured without SCENEFILE_VULKAN)";
#endif
  return probe;
}

bool autoPrefersGpu(const RenderSettings& settings) {
  if (samplesAdaptively(settings)) return false;
  std::uint64_t threads = static_cast<std::uint64_t>(resolveThreads(settings.threads));
  return uniformSampleCount(settings) >= kAutoGpuMinSamplesPerThread * threads;
}

RenderDevice chooseDevice(const RenderSettings& settings) {
  if (settings.device != RenderDevice::Auto) return settings.device;
  if (!autoPrefersGpu(settings)) return RenderDevice::Cpu;
  return probeGpu(false).available ? RenderDevice::Gpu : RenderDevice::Cpu;
}

}  // namespace render
