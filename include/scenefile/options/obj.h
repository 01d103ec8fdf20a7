/// @file
/// What reading and writing Wavefront OBJ (.obj, with its .mtl) can be told
/// beyond the common options.
#pragma once

#include <cstddef>
#include <string>

#include "scenefile/mesh.h"
#include "scenefile/options/gltf.h"

namespace scene {

/// Options of the OBJ reader.
struct ObjReadOptions {
  /// More `v` vertices than this in the file is obj-too-large; faces are
  /// held to three times as many triangle corners. glTF's limit.
  std::size_t maxVertices = kDefaultMaxGltfVertices;

  friend bool operator==(const ObjReadOptions&, const ObjReadOptions&) = default;
};

/// Options of the OBJ writer.
struct ObjWriteOptions {
  /// The name of the MTL file written beside the OBJ (its `mtllib`); empty
  /// writes no MTL, and the materials ride in the comments alone.
  std::string materialLibrary;
  /// How finely curved surfaces are tessellated (scenefile/mesh.h).
  int segments = kDefaultSegments;

  friend bool operator==(const ObjWriteOptions&, const ObjWriteOptions&) = default;
};

}  // namespace scene
