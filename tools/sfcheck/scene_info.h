// sfcheck --info: what a file holds, as `assimp info` tells it: the format
// and size, the objects by kind, the lights, the camera, the box of the
// finite objects and the distinct materials.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "scenefile/format.h"
#include "scenefile/scene.h"

namespace tools {

// The text form, one fact a line, the file first:
//
//   scene.sf: a scene file, 412 bytes
//     objects: 3 (1 plane, 1 sphere, 0 cylinders, 1 cube)
//     lights: 1
//     camera: at (0 1 5), looking along (0 0 -1)
//     box: (-1 -1 -1) to (1 3 1), and 1 plane, infinite
//     materials: 2 distinct
//
// Numbers have 6 significant digits; the camera's field of view shows where
// the file gives one (a POV-Ray or glTF camera).
std::string sceneInfoText(const std::string& shown, scene::Format format, std::uintmax_t bytes,
                          const scene::Scene& scene);

// The JSON form, exact numbers: bytes, objects (total and by kind),
// lights, materials, camera (position, direction, up, and verticalFov and
// aspectRatio where the file gives them), bounds ({low, high} or null) and
// unbounded (the objects outside bounds).
nlohmann::json sceneInfoJson(std::uintmax_t bytes, const scene::Scene& scene);

}  // namespace tools
