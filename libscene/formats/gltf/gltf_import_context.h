// What the parts of the glTF import share once tinygltf has read the model
// (the node walk, cameras and lights, materials, meshes): the model and our
// own extras, the scene they fill, where diagnostics go and what a loss is;
// and the labels of the file's nodes and meshes (gltf_labels.h).
#pragma once

#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>
#include <string>

#include "libscene/formats/gltf/gltf_document.h"
#include "libscene/formats/gltf/gltf_labels.h"
#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene::gltf {

struct ImportContext {
  const tinygltf::Model& model;
  const OwnExtras& own;
  Scene& scene;
  DiagnosticList& out;
  // What the scene cannot carry over: a warning, or an error under noLoss.
  Severity loss;
};

// The light that a node's KHR_lights_punctual points at: -1 when it has
// none, -2 when its index is not one.
int nodeLight(const tinygltf::Model& model, int node);

// Whether every entry is finite: finite values can compose to infinity,
// which the scene must not hold.
bool finite(const glm::dmat4& m);

}  // namespace scene::gltf
