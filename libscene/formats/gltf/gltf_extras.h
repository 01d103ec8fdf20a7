// Our own extras: the exact values that the glTF writer puts under
// `extras.sf` (docs/GLTF.md, "Extras"), read back by the glTF reader.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace scene::gltf {

// A JSON number that is finite, else nothing.
std::optional<double> number(const nlohmann::json& j);
// The JSON of `text`, or null when it is empty or not JSON.
nlohmann::json parseOrNull(const std::string& text);
// The `sf` object of an `extras` value, if it has one.
const nlohmann::json* sfExtras(const nlohmann::json& extras);

// A node's record as its extras describe it.
struct RecordExtras {
  std::string record;
  glm::dvec3 colour{0.0};
  glm::dmat4 matrix{1.0};
  std::optional<glm::dvec3> lookAt;
  std::optional<std::vector<TransformOp>> transforms;
  // CAMERA: the scene had no View, and the camera's yfov is only the
  // writer's default ("view": false), so that reading back gives no View.
  bool noView = false;
};

// The record of a node's extras (JSON text), when they hold a whole one;
// `transforms` only while they still compose to the matrix.
std::optional<RecordExtras> recordExtras(const std::string& extrasText);
// The material of a material's extras, when they hold every value.
std::optional<Material> materialExtras(const std::string& extrasText);

}  // namespace scene::gltf
