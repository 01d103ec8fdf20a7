// The glTF 2.0 writer (.gltf with its buffer embedded or beside it, or .glb).
#pragma once

#include <optional>
#include <string>

#include "libscene/diagnostic.h"
#include "libscene/gltf_mapping.h"
#include "libscene/mesh.h"
#include "libscene/scene.h"

namespace scene {

struct GltfWriteOptions {
  // One .glb file instead of JSON text.
  bool binary = false;
  // For JSON text: the name of a buffer file to write beside it (its URI);
  // empty embeds the buffer as base64.
  std::string externalBuffer;
  // The camera's vertical field of view; a scene file holds none.
  double yfovDegrees = gltf::kDefaultYfovDegrees;
  // The image size, for the camera's aspect ratio; 0 leaves it out.
  int width = 0;
  int height = 0;
  int segments = kDefaultSegments;
  // Every loss is an error, and nothing is written.
  bool noLoss = false;
  std::string generator = "scenefile";
};

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
std::optional<GltfFiles> writeGltf(const Scene& scene, const GltfWriteOptions& options,
                                   DiagnosticList& out);

}  // namespace scene
