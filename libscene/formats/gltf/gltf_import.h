// The scene of a glTF model that tinygltf has read: every index checked,
// then the default scene's node hierarchy walked and flattened into world
// matrices, each node giving its records (the CAMERA, LIGHTs, objects):
// from our own extras when they still match the node, else from its
// camera, light and mesh.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <map>
#include <string>
#include <vector>

#include "libscene/formats/gltf/gltf_cameras_lights.h"
#include "libscene/formats/gltf/gltf_document.h"
#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_import_context.h"
#include "libscene/formats/gltf/gltf_materials.h"
#include "libscene/formats/gltf/gltf_meshes.h"
#include "scenefile/read.h"

namespace scene::gltf {

class Importer {
 public:
  // Fills result.scene and reports in result.diagnostics.
  Importer(const tinygltf::Model& model, const OwnExtras& own, const ReadOptions& options,
           ReadResult& result);

  void run();

 private:
  bool index(int value, std::size_t size, const std::string& where, const std::string& what,
             bool optional = true);
  bool checkIndices();
  std::vector<int> rootNodes();
  void walk(const std::vector<int>& roots);
  void visit(int node, const glm::dmat4& world);
  bool useExtras(int node, const glm::dmat4& world, const RecordExtras& extras);
  void addMeshObjects(int node, const glm::dmat4& world);
  void addInstance(int node, std::size_t instance, const glm::dmat4& world);
  bool roomForOne(int node);
  void restoreObjectOrder();

  ImportContext c_;
  CamerasAndLights camerasAndLights_;
  MaterialReader materials_;
  MeshReader meshes_;
  std::size_t maxObjects_;
  bool stopped_ = false;  // past maxObjects: the walk ends
  // The number (RecordExtras::object) of each object read so far, while
  // every one of them has one.
  std::vector<std::size_t> numbers_;
  // The objects of each instanced mesh's extras not yet found (meshRecords).
  std::map<int, std::vector<RecordExtras>> meshRecords_;
};

}  // namespace scene::gltf
