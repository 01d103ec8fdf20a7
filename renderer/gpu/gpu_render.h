// renderImage and renderObjectIds on a Vulkan device (RenderDevice::Gpu):
// the compute shader of render.comp, one thread a pixel, in bands of rows
// so that a render can be cancelled and report progress between them.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/gpu/vulkan_context.h"
#include "renderer/render.h"

namespace render::gpu {

Image renderImageGpu(const RenderScene& scene, const RenderSettings& settings,
                     RenderStatistics* statistics, const ProgressCallback& progress,
                     const CancelFlag* cancel);

std::vector<std::int32_t> renderObjectIdsGpu(const RenderScene& scene,
                                             const RenderSettings& settings);

}  // namespace render::gpu
