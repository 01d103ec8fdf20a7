// The scene built from what a POV-Ray file's statements gathered: a
// left-handed world mirrored into the renderer's right-handed one, the camera
// matrix and view from POV-Ray's camera vectors, each object's material
// from its texture over #default, and the exact values of the
// exact-value comments wherever they still describe the statement
// they stand before. Every value the model cannot hold is reported.
#pragma once

#include <vector>

#include "libscene/formats/pov/pov_import.h"
#include "libscene/formats/pov/pov_lexer.h"
#include "libscene/formats/pov/pov_scene_parts.h"

namespace scene {

// Fills `result` (its scene, view and objectEnds, and diagnostics) from
// `parts`; `defaults` is #default's texture, `comments` the file's exact
// comments, which the parts index.
void buildPovScene(const PovSceneParts& parts, const PovMaterialPatch& defaults,
                   const std::vector<PovLexer::ExactComment>& comments, const ReadOptions& options,
                   PovImport& result);

}  // namespace scene
