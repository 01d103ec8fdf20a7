// The scene's own view in a render's settings, for every front end that
// renders (sfrender, the language server's render command).
#pragma once

#include <optional>

#include "renderer/render.h"
#include "scenefile/scene.h"

namespace tools {

// The scene's own view (a POV-Ray or glTF camera's) where the caller does
// not say otherwise: its field of view unless `fovGiven`, and at its aspect
// ratio the side that `width` and `height` leave open (the height, when
// neither is given). `settings` holds the sizes and field of view to start
// from.
void applySceneView(const scene::Scene& scene, std::optional<int> width, std::optional<int> height,
                    bool fovGiven, render::RenderSettings& settings);

}  // namespace tools
