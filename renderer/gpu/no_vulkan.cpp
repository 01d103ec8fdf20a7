// The GPU path in a build without Vulkan (SCENEFILE_VULKAN off): there is no
// device, and everything that would use one says why.
#include "renderer/device.h"
#include "renderer/gpu/gpu_render.h"

namespace render {

GpuProbe probeGpu(bool) {
  GpuProbe probe;
  probe.reason = "this build has no Vulkan (configured without SCENEFILE_VULKAN)";
  return probe;
}

// Never made: the constructor throws. Its members still have to be there.
struct GpuDevice::Device {
  std::string name;
};

GpuDevice::GpuDevice() {
  throw DeviceUnavailable(probeGpu().reason);
}
GpuDevice::~GpuDevice() = default;
const std::string& GpuDevice::name() const {
  return device_->name;
}
bool GpuDevice::isCpu() const {
  return false;
}
const gpu::VulkanContext& GpuDevice::vulkan() const {
  throw DeviceUnavailable(probeGpu().reason);
}

namespace gpu {

Image renderImageGpu(const RenderScene&, const RenderSettings&, RenderStatistics*,
                     const ProgressCallback&, const CancelFlag*) {
  throw DeviceUnavailable(probeGpu().reason);
}

std::vector<std::int32_t> renderObjectIdsGpu(const RenderScene&, const RenderSettings&) {
  throw DeviceUnavailable(probeGpu().reason);
}

}  // namespace gpu

}  // namespace render
