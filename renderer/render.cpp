#include "renderer/render.h"

#include "renderer/cpu_render.h"
#include "renderer/gpu/gpu_render.h"

namespace render {

Image renderImage(const RenderScene& scene, const RenderSettings& settings,
                  RenderStatistics* statistics, const ProgressCallback& progress,
                  const CancelFlag* cancel) {
  if (chooseDevice(settings) == RenderDevice::Gpu) {
    // The GPU path's refusal, before any device is touched.
    if (samplesAdaptively(settings)) {
      throw DeviceUnavailable("adaptive anti-aliasing is not done on the gpu");
    }
    return gpu::renderImageGpu(scene, settings, statistics, progress, cancel);
  }
  return renderImageCpu(scene, settings, statistics, progress, cancel);
}

std::vector<std::int32_t> renderObjectIds(const RenderScene& scene,
                                          const RenderSettings& settings) {
  if (chooseDevice(settings) == RenderDevice::Gpu) return gpu::renderObjectIdsGpu(scene, settings);
  return renderObjectIdsCpu(scene, settings);
}

}  // namespace render
