// The glTF's cameras and lights as the scene's CAMERA and LIGHTs: the first
// camera found is the CAMERA (its field of view a View), every light a
// point light; what a scene file cannot hold (a directional light's
// direction, a spot's cone, the fall-off) is reported.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_import_context.h"
#include "libscene/formats/gltf/gltf_light_units.h"
#include "libscene/formats/gltf/gltf_mapping.h"

namespace scene::gltf {

class CamerasAndLights {
 public:
  explicit CamerasAndLights(const ImportContext& context) : c_(context) {}

  // The CAMERA from node `node`'s camera, at `world` (the node's matrix
  // composed with its parents'), unless the scene has one already.
  void addCamera(int node, const glm::dmat4& world);
  // A LIGHT from light `light` on node `node`.
  void addLight(int node, int light, const glm::dmat4& world);

  // The CAMERA or LIGHT exactly as our extras hold it, when they still
  // describe the node; false, and nothing added, when they do not.
  bool cameraFromExtras(int node, const glm::dmat4& world, const RecordExtras& extras);
  bool lightFromExtras(int node, const glm::dmat4& world, const RecordExtras& extras);

  // After the walk, when every object is known: directional lights are
  // placed beyond the scene, a file without a camera gets one that sees
  // every object, and the point and spot lights get their colours at their
  // reference distances in the scene read (gltf_reference_point.h).
  void finish();

 private:
  void reportFov(int camera);
  void placeDirectionalLights();
  void makeDefaultCamera();
  void colourPointLights();
  static PointLight pointLight(const tinygltf::Light& light);

  const ImportContext& c_;
  bool haveCamera_ = false;
  // Directional lights (the index of each in scene.lights, and the
  // direction it shines in), placed once the scene's extent is known.
  std::vector<std::pair<std::size_t, glm::dvec3>> pendingDirectional_;
  // Point and spot lights (the index of each in scene.lights, its glTF
  // values and its name for messages), coloured once the scene is known.
  struct PendingPoint {
    std::size_t light = 0;
    PointLight point;
    std::string label;
  };
  std::vector<PendingPoint> pendingPoint_;
};

}  // namespace scene::gltf
