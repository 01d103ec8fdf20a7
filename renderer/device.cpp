// Auto's choice. The probe and GpuDevice are the GPU path's
// (renderer/gpu/vulkan_device.cpp, or renderer/gpu/no_vulkan.cpp in a build
// without Vulkan).
#include "renderer/device.h"

#include <cstdint>

#include "renderer/parallel_parts.h"
#include "renderer/render_settings.h"

namespace render {

bool autoPrefersGpu(const RenderSettings& settings) {
  if (samplesAdaptively(settings)) return false;
  std::uint64_t threads = static_cast<std::uint64_t>(resolveThreads(settings.threads));
  return uniformSampleCount(settings) >= kAutoGpuMinSamplesPerThread * threads;
}

RenderDevice chooseDevice(const RenderSettings& settings) {
  if (settings.device != RenderDevice::Auto) return settings.device;
  if (!autoPrefersGpu(settings)) return RenderDevice::Cpu;
  bool realGpu = settings.gpu ? !settings.gpu->isCpu() : probeGpu(false).available;
  return realGpu ? RenderDevice::Gpu : RenderDevice::Cpu;
}

}  // namespace render
