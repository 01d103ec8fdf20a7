// The probe and GpuDevice in a build with Vulkan: VulkanContext's.
#include <memory>

#include "renderer/device.h"
#include "renderer/gpu/vulkan_context.h"

namespace render {

GpuProbe probeGpu(bool allowCpu) {
  GpuProbe probe;
  gpu::DeviceProbe found = gpu::VulkanContext::probe(allowCpu);
  probe.available = found.found;
  probe.isCpu = found.isCpu;
  probe.name = found.name;
  probe.reason = found.reason;
  return probe;
}

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

GpuDevice::~GpuDevice() = default;

const std::string& GpuDevice::name() const {
  return device_->context.name();
}
bool GpuDevice::isCpu() const {
  return device_->context.isCpu();
}
const gpu::VulkanContext& GpuDevice::vulkan() const {
  return device_->context;
}

}  // namespace render
