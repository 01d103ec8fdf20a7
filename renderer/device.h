// The GPU a render can trace on: a Vulkan device kept open (GpuDevice), the
// probe for one, and the device RenderDevice::Auto chooses
// (docs/RENDERING.md, "The GPU path").
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "renderer/render_settings.h"

namespace render {

// Auto's threshold: a GPU render first pays a fixed start (instance, device,
// the pipeline's compilation, the scene's upload, the readback: about 0.25 s
// on an NVIDIA H200, whatever the samples), while the CPU's time grows with
// the samples each thread traces. There the GPU came out ahead from half a
// million to a million samples a thread against 2 threads and from one to
// two million against 16 (docs/PERFORMANCE.md, "GPU (Vulkan)").
inline constexpr std::uint64_t kAutoGpuMinSamplesPerThread = 1'000'000;

namespace gpu {
class VulkanContext;
}

// Why a render cannot run on the device asked for: no Vulkan device with
// doubles, a build without Vulkan, or a setting the GPU path does not do.
class DeviceUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A Vulkan device opened once for many GPU renders (RenderSettings::gpu),
// the first that fits as the GPU path takes it (a real GPU before a CPU
// implementation). Renders through it skip the device's start (0.16 s on
// an NVIDIA H200), and the driver stays loaded between them: a render that
// opens its own device loads the driver and unloads it after, and NVIDIA's
// (580) keeps some of the process's static TLS each time, so that after
// about 30 loads in one process no instance can be made (docs/RENDERING.md,
// "The GPU path"). One render at a time goes through it.
class GpuDevice {
 public:
  // Throws DeviceUnavailable where no device fits or the build has no
  // Vulkan.
  GpuDevice();
  ~GpuDevice();
  GpuDevice(const GpuDevice&) = delete;
  GpuDevice& operator=(const GpuDevice&) = delete;

  const std::string& name() const;
  // A CPU implementation such as lavapipe.
  bool isCpu() const;
  // What the GPU path renders with (renderer/gpu).
  const gpu::VulkanContext& vulkan() const;

 private:
  struct Device;
  std::unique_ptr<Device> device_;
};

// Whether the GPU path can run here, and on what.
struct GpuProbe {
  bool available = false;
  bool isCpu = false;  // a CPU implementation such as lavapipe
  std::string name;
  std::string reason;  // why not, when not available
};
// Looks for a Vulkan device with shaderFloat64 and shaderInt64 (a real GPU
// first); with `allowCpu` false a CPU implementation does not count.
GpuProbe probeGpu(bool allowCpu = true);

// Whether a render with `settings` is one Auto gives a real GPU where one is
// present: uniform, with at least kAutoGpuMinSamplesPerThread camera samples
// for each thread of settings.threads.
bool autoPrefersGpu(const RenderSettings& settings);

// The device a render with `settings` runs on: Auto decided (autoPrefersGpu,
// then probing for a GPU), Cpu and Gpu as they are.
RenderDevice chooseDevice(const RenderSettings& settings);

}  // namespace render
