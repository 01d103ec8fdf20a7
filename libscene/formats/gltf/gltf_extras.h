// Our own extras: the exact values that the glTF writer puts under
// `extras.sf` (docs/GLTF.md, "Extras"), read back by the glTF reader, and
// what tells whether they still describe the file's own data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "libscene/formats/gltf/gltf_mapping.h"
#include "scenefile/scene.h"
#include "scenefile/transform.h"

namespace scene::gltf {

// A JSON number that is finite, else nothing.
std::optional<double> number(const nlohmann::json& j);
// A number of our own extras: as number(), or the string "-0" for a
// negative zero (extrasJson).
std::optional<double> extrasNumber(const nlohmann::json& j);
// The `extras` value that holds our own values `sf`, each negative zero as
// the string "-0": JavaScript writes -0 as 0 in JSON, so a file passed
// through a JavaScript program (glTF-Transform, for one) would otherwise
// lose the sign that a scene file's matrix keeps.
nlohmann::json extrasJson(nlohmann::json sf);
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
  // LIGHT: the distance at which the writer matched the glTF light to the
  // colour (gltf_light_units.h); files written before it have none.
  std::optional<double> referenceDistance;
  // An object's number in the scene (1 for the first), by which the reader
  // restores the scene's order; files written before it have none.
  std::optional<std::size_t> object;
};

// The record of a node's extras (JSON text), when they hold a whole one;
// `transforms` only while they still compose to the matrix.
std::optional<RecordExtras> recordExtras(const std::string& extrasText);
// The objects that a mesh's extras describe (`objects`): every object the
// writer drew with the mesh, so that they are found again when a program
// has replaced their nodes by instances of the mesh (EXT_mesh_gpu_instancing).
std::vector<RecordExtras> meshRecords(const std::string& extrasText);
// The material of a material's extras, when they hold every value.
std::optional<Material> materialExtras(const std::string& extrasText);

// The extras are believed only while they agree with the glTF values: a
// difference above this (relative) means the file was edited elsewhere.
inline constexpr double kExtrasAgreement = 1e-9;
// An instance (EXT_mesh_gpu_instancing) stands for an object of its mesh's
// extras when its matrix lies this close (instanceDistance): its
// translation, rotation and scale are floats, rounded to about 6e-8.
inline constexpr double kInstanceAgreement = 1e-6;

// The extras (OwnExtras) of object `index`, "" when it has none.
const std::string& ownExtras(const std::vector<std::string>& extras, int index);

// The largest difference between two glTF materials' values: infinite when
// one has an extension value that the other has not.
double distanceOfPbr(const PbrMaterial& a, const PbrMaterial& b);

// The tessellation (segments) that gives the writer's mesh of `kind` this many
// triangles, if one does.
std::optional<int> writtenSegments(ObjectKind kind, std::size_t triangles);
// Whether the triangles (three indices into `positions` each) are exactly
// the writer's mesh of `kind` (scenefile/mesh.h) at some tessellation, a
// plane's at the size its corners give: the same triangles, each turning the
// same way, in any order, with vertices at one place shared or not. So the
// order of the vertices and of the triangles, and which vertices are
// merged, do not matter (glTF-Transform's weld and reorder change them);
// any coordinate that moved does.
bool isWrittenMesh(ObjectKind kind, const std::vector<glm::dvec3>& positions,
                   const std::vector<std::uint32_t>& indices);

}  // namespace scene::gltf
