// What a hover says of the parts of a read scene, as Markdown: an object's
// kind, material and world-space bounds, the camera's view, a light, a
// matrix. Numbers are written as the writers write them: the shortest text
// that reads back to the same double.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "scenefile/scene.h"

namespace sfls {

// The shortest text that reads back to `value`'s bits.
std::string numberText(double value);
// "x y z", each as numberText.
std::string vectorText(const glm::dvec3& value);

// A 4x4 matrix row by row, as a file writes it, in a code block.
std::string matrixMarkdown(const glm::dmat4& matrix);

// The object's material (each value, defaults marked) and its world-space
// bounds (a plane has none).
std::string describeObject(const scene::Object& object);

// The camera's eye, forward and up (orthonormalised, as the renderer takes
// them) and the vertical field of view a render takes by default.
std::string describeCamera(const scene::Scene& scene);

// The light's position and colour.
std::string describeLight(const scene::Light& light);

}  // namespace sfls
