// The glTF's JSON document before tinygltf sees it: how many objects it
// holds, whether every index in it is an index, and what of it tinygltf is
// given. tinygltf drops an index of the wrong type in silence and copies
// every object into a struct of hundreds of bytes, so both are settled here.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/diagnostic.h"

namespace scene::gltf {

// The weighted count of scanJson (gltf_json_scan.h, which counts from the
// bytes before anything is parsed) over the parsed document, with the
// primitives of every mesh and KHR_lights_punctual's lights included.
std::size_t countObjects(const nlohmann::json& doc);

// How far from 1 a node's rotation quaternion may be in length (the Khronos
// glTF Validator's ROTATION_NON_UNIT threshold, which allows for rotations
// stored in 8 bits); the reader normalises what lies within it.
inline constexpr double kUnitQuaternionTolerance = 0.00769;

// A problem found in the document, at the JSON pointer of the value.
struct DocumentProblem {
  Severity severity = Severity::Error;
  DiagnosticCode code = DiagnosticCode::GltfInvalid;
  std::string pointer;
  std::string message;
  std::string hint;
  std::vector<Remedy> remedies;  // Diagnostic::remedies
};

// Every index of the document that the reader follows (scene, scenes' nodes,
// nodes' children, mesh, camera and light, primitives' attributes, indices,
// material and targets, accessors' buffer views, views' buffers, textures'
// sources and samplers, materials' textures) must be a whole number from 0
// below the size of the array it points into; every object array must hold
// objects, and every mesh at least one primitive (the glTF 2.0 schema).
// A node's matrix, translation, rotation and scale must be arrays of 16, 3,
// 4 and 3 finite numbers, a matrix never beside the others, a rotation a
// unit quaternion. Values are checked where the schema bounds them (a camera's yfov,
// aspectRatio and znear above 0; a light's colour in [0, 1], intensity from
// 0, range above 0; emissiveFactor in [0, 1]); what a scene file cannot hold
// (emission, aspectRatio, range, a yfov from pi) is a loss: a warning, or an
// error under `noLoss`.
std::vector<DocumentProblem> checkDocument(const nlohmann::json& doc, bool noLoss);

// Reports the problems, each at the line and column of its pointer's value
// in `text` (the .gltf, from which `json` is a part starting at `offset`),
// or without a span when `text` is empty (a GLB's JSON chunk).
void reportProblems(const std::vector<DocumentProblem>& problems, std::string_view text,
                    std::size_t offset, DiagnosticList& out);

// What of `extras` the reader uses: the `sf` object of each node, material
// and mesh, as JSON text ("" when there is none).
struct OwnExtras {
  std::vector<std::string> nodes;
  std::vector<std::string> materials;
  std::vector<std::string> meshes;
};

// Takes our own extras out of the document, removes every other `extras`
// and every extension the reader does not read, so that tinygltf, which
// turns extras and extensions into values of 152 bytes each, copies none of
// what the reader ignores.
OwnExtras trimForTinygltf(nlohmann::json& doc);

}  // namespace scene::gltf
