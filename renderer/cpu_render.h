// renderImage and renderObjectIds on the CPU's threads (RenderDevice::Cpu):
// stratified samples with a seed, adaptive depth control and sampling, the
// image in square tiles that the threads take in turn.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/image.h"
#include "renderer/render_progress.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "renderer/render_statistics.h"

namespace render {

Image renderImageCpu(const RenderScene& scene, const RenderSettings& settings,
                     RenderStatistics* statistics, const ProgressCallback& progress,
                     const CancelFlag* cancel);

std::vector<std::int32_t> renderObjectIdsCpu(const RenderScene& scene,
                                             const RenderSettings& settings);

}  // namespace render
