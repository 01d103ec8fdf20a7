// Which device renders: the Vulkan probe and the choice of `auto`
// (docs/RENDERING.md, "The GPU path").
#include <cstdint>
#include <memory>

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
  bool realGpu = settings.gpu ? !settings.gpu->isCpu() : probeGpu(false).available;
  return realGpu ? RenderDevice::Gpu : RenderDevice::Cpu;
}

#if SCENEFILE_VULKAN
struct GpuDevice::Device {
  gpu::VulkanContext context;
};

GpuDevice::GpuDevice() {
  try {
    device_ = std::make_unique<Device>();
  } catch (const gpu::VulkanError& e) {
    throw DeviceUnavailable(e.what());
  }
}

const std::string& GpuDevice::name() const {
  return device_->context.name();
}
bool GpuDevice::isCpu() const {
  return device_->context.isCpu();
}
const gpu::VulkanContext& GpuDevice::vulkan() const {
  return device_->context;
}
#else
// Never made: the constructor throws. Its members still have to be there.
struct GpuDevice::Device {
  std::string name;
};

GpuDevice::GpuDevice() {
  throw DeviceUnavailable(probeGpu().reason);
}
const std::string& GpuDevice::name() const {
  return device_->name;
}
bool GpuDevice::isCpu() const {
  return false;
}
const gpu::VulkanContext& GpuDevice::vulkan() const {
  throw DeviceUnavailable(probeGpu().reason);
}
#endif

GpuDevice::~GpuDevice() = default;

}  // namespace render
