// Rendering a whole image on the device the settings choose: the one place
// that knows both the CPU path (cpu_render.h) and the GPU path
// (renderer/gpu).
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/device.h"
#include "renderer/image.h"
#include "renderer/render_progress.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "renderer/render_statistics.h"

namespace render {

// The image of `scene`. With `cancel`, stops once it is requested: every
// thread leaves its row, and RenderCancelled is thrown when all are joined.
Image renderImage(const RenderScene& scene, const RenderSettings& settings,
                  RenderStatistics* statistics = nullptr, const ProgressCallback& progress = {},
                  const CancelFlag* cancel = nullptr);

// The index of the object each pixel's centre ray meets first, or -1: the
// picture that geometry tests compare (of the whole image, whatever the
// region).
std::vector<std::int32_t> renderObjectIds(const RenderScene& scene, const RenderSettings& settings);

}  // namespace render
