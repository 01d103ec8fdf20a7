// The scene file (.sf) writer.
#pragma once

#include <string>

#include "scenefile/scene.h"

namespace scene {

// The scene as a scene file: the camera, then the lights, then the objects,
// one blank line between records, every number in its shortest exact form.
// Material values other than COLOUR have no place in the format and are not
// written; convertScene reports them.
std::string writeSceneFile(const Scene& scene);

}  // namespace scene
