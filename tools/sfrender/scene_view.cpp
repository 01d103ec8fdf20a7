#include "tools/sfrender/scene_view.h"

#include <algorithm>
#include <cmath>

#include "scenefile/validation.h"

namespace tools {

void applySceneView(const scene::Scene& scene, std::optional<int> width, std::optional<int> height,
                    bool fovGiven, render::RenderSettings& settings) {
  if (!scene.view) return;
  if (!fovGiven) {
    settings.verticalFovDegrees =
        std::clamp(scene.view->verticalFovDegrees, scene::kMinFovDegrees, scene::kMaxFovDegrees);
  }
  if (!scene.view->aspectRatio || (height && width)) return;
  double aspect = *scene.view->aspectRatio;
  auto side = [](double pixels) {
    return static_cast<int>(std::clamp(std::round(pixels), 1.0, double{scene::kMaxImageSide}));
  };
  if (height) {
    settings.width = side(settings.height * aspect);
  } else {
    settings.height = side(settings.width / aspect);
  }
}

}  // namespace tools
