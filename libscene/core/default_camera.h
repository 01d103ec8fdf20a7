// The camera a reader gives a file that has none (glTF without a camera,
// OBJ): on +Z of the objects' centres, far enough back to see them all.
#pragma once

#include <glm/mat4x4.hpp>
#include <optional>
#include <span>

#include "scenefile/scene.h"

namespace scene {

/// The camera matrix looking down -Z at the middle of the objects' centres
/// from twice their spread plus 5 away; nothing where that place is not
/// finite (the reader reports it). Objects whose centre is not finite are
/// left out.
std::optional<glm::dmat4> cameraSeeingObjects(std::span<const Object> objects);

}  // namespace scene
