// The glTF 2.0 writer (.gltf with its buffer embedded or beside it, or .glb).
#pragma once

#include <optional>
#include <string>

#include "scenefile/diagnostic.h"
#include "libscene/formats/gltf/gltf_mapping.h"
#include "scenefile/convert.h"
#include "scenefile/mesh.h"
#include "scenefile/scene.h"

namespace scene {


struct GltfFiles {
  // The .gltf text or the .glb bytes.
  std::string main;
  // The buffer's bytes when options.externalBuffer names a file, else empty.
  std::string buffer;
};

// The scene as glTF: every object a node with its matrix and a mesh of its
// primitive (meshes of one kind share their vertex data), the camera a
// perspective camera on its own node, lights KHR_lights_punctual point
// lights, materials metallic-roughness with the exact values in `extras`.
// Each value glTF cannot hold is reported in `out` (a warning, or an error
// under noLoss, and then nothing is returned); what rides in extras alone
// gets a note.
std::optional<GltfFiles> writeGltf(const Scene& scene, const ConversionOptions& options,
                                   bool binary, DiagnosticList& out);

}  // namespace scene
