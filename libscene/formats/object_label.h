// How a writer's diagnostics name an object of the scene it writes.
#pragma once

#include <cstddef>
#include <string>

#include "scenefile/scene.h"

namespace scene {

// The object's kind and its number in the scene, counted from 1:
// "SPHERE object 3".
inline std::string objectLabel(const Object& object, std::size_t index) {
  return std::string(objectKindName(object.kind)) + " object " + std::to_string(index + 1);
}

}  // namespace scene
