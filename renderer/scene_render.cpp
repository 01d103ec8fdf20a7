// The public render API (scenefile/render.h) over the renderer: the one
// place that turns the public settings into the renderer's.
#include <algorithm>
#include <cmath>
#include <stop_token>

#include "renderer/image.h"
#include "renderer/render.h"
#include "renderer/render_scene.h"
#include "renderer/saturating.h"
#include "scenefile/render.h"
#include "scenefile/validation.h"

namespace scene {

std::uint64_t RenderedImage::bytesFor(int width, int height, bool withCoverage) {
  std::uint64_t pixels =
      render::saturatingProduct(static_cast<std::uint64_t>(width > 0 ? width : 0),
                                static_cast<std::uint64_t>(height > 0 ? height : 0));
  return render::saturatingProduct(pixels, (kChannels + (withCoverage ? 1 : 0)) * sizeof(float));
}

void applySceneView(const Scene& scene, std::optional<int> width, std::optional<int> height,
                    bool fovGiven, RenderSettings& settings) {
  if (!scene.view) return;
  if (!fovGiven) {
    settings.verticalFovDegrees =
        std::clamp(scene.view->verticalFovDegrees, kMinFovDegrees, kMaxFovDegrees);
  }
  if (!scene.view->aspectRatio || (height && width)) return;
  double aspect = *scene.view->aspectRatio;
  auto side = [](double pixels) {
    return static_cast<int>(std::clamp(std::round(pixels), 1.0, double{kMaxImageSide}));
  };
  if (height) {
    settings.width = side(settings.height * aspect);
  } else {
    settings.height = side(settings.width / aspect);
  }
}

RenderedImage renderScene(const Scene& scene, const RenderSettings& settings,
                          const RenderControl& control) {
  render::RenderSettings full;
  static_cast<RenderSettings&>(full) = settings;
  // The renderer reads a flag that a signal handler may set; a stop
  // request sets it.
  render::CancelFlag cancel;
  std::stop_callback onStop(control.stop, [&cancel] { cancel.request(); });
  render::RenderScene compiled(
      scene, 0,
      render::RenderScene::lightGridsPay(scene.objects.size(), render::uniformSampleCount(full)),
      render::fullImageSampleCount(full));
  return render::renderImage(compiled, full, nullptr, control.progress, &cancel);
}

std::vector<std::uint8_t> eightBitLevels(const RenderedImage& image) {
  std::vector<std::uint8_t> levels(image.rgb.size());
  render::eightBitLevels(image.rgb.data(), image.rgb.size(), levels.data());
  return levels;
}

std::vector<float> linearValues(const RenderedImage& image) {
  std::vector<float> linear(image.rgb.size());
  for (std::size_t i = 0; i < linear.size(); ++i) linear[i] = render::srgbToLinear(image.rgb[i]);
  return linear;
}

}  // namespace scene
