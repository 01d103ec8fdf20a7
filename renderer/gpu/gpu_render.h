// renderImage and renderObjectIds on a Vulkan device (RenderDevice::Gpu):
// the compute shader of render.comp, one thread a pixel, in bands of rows
// so that a render can be cancelled and report progress between them. Both
// throw DeviceUnavailable where no device fits, a Vulkan call fails or the
// build has no Vulkan (no_vulkan.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/image.h"
#include "renderer/render_progress.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "renderer/render_statistics.h"

namespace render::gpu {

Image renderImageGpu(const RenderScene& scene, const RenderSettings& settings,
                     RenderStatistics* statistics, const ProgressCallback& progress,
                     const CancelFlag* cancel);

std::vector<std::int32_t> renderObjectIdsGpu(const RenderScene& scene,
                                             const RenderSettings& settings);

}  // namespace render::gpu
