// The glTF's materials as the scene's: from our own extras while they still
// match the glTF values, else from the metallic-roughness values and the
// KHR_materials_ior, _transmission and _specular extensions (gltf_mapping.h).
#pragma once

#include <set>

#include "libscene/formats/gltf/gltf_import_context.h"
#include "libscene/formats/gltf/gltf_mapping.h"
#include "scenefile/scene.h"

namespace scene::gltf {

class MaterialReader {
 public:
  explicit MaterialReader(const ImportContext& context) : c_(context) {}

  // The material of glTF material `index` (-1: none, the default) on an
  // object of `kind`. What it loses (a texture, an alpha) is reported once
  // per material, however many objects use it.
  Material material(int index, ObjectKind kind);

 private:
  void reportLosses(int index, const PbrMaterial& pbr);

  const ImportContext& c_;
  std::set<int> reported_;
};

}  // namespace scene::gltf
