// Which device renders: the Vulkan probe and the choice of `auto`
// (docs/RENDERING.md, "The GPU path").
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

RenderDevice chooseDevice(const RenderSettings& settings) {
  if (settings.device != RenderDevice::Auto) return settings.device;
  if (samplesAdaptively(settings)) return RenderDevice::Cpu;
  if (uniformSampleCount(settings) < kAutoGpuMinSamples) return RenderDevice::Cpu;
  return probeGpu(false).available ? RenderDevice::Gpu : RenderDevice::Cpu;
}

}  // namespace render
