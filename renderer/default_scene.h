// The scene sfrender draws when it is given none.
#pragma once

#include "scenefile/scene.h"

namespace render {

// A floor, a mirror, a glass sphere, and a sphere, a cube and a cylinder
// under two lights: every primitive and every material effect.
scene::Scene defaultScene();

}  // namespace render
