// What every reader takes and gives back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

// The default limits on what one input may cost (docs/FORMATS.md, "Limits").
// They bound the memory and time a hostile or mistaken file can take; each
// has a flag on the tools that raises it.
inline constexpr std::uint64_t kDefaultMaxFileSize = std::uint64_t{1} << 30;  // 1 GiB
// Objects and lights together: each costs memory when read and time when
// rendered (every light at every shading point).
inline constexpr std::size_t kDefaultMaxObjects = 5'000'000;
// POSITION vertices read from one glTF file, all meshes together; indices
// are held to three times as many.
inline constexpr std::size_t kDefaultMaxGltfVertices = std::size_t{1} << 24;
// Nodes and every other glTF object (docs/GLTF.md, "Hostile files"):
// tinygltf holds each in hundreds of bytes, however few the file spends.
inline constexpr std::size_t kDefaultMaxGltfNodes = 1'000'000;

struct ReadOptions {
  // Read each 4x4 of a scene file column by column: the repair for files
  // written transposed (sfconvert --transpose-matrices).
  bool transposedMatrices = false;
  std::size_t errorLimit = DiagnosticList::kDefaultErrorLimit;
  // What a reader cannot carry over into the scene (a glTF mesh that is no
  // primitive, a spot light made a point light) is an error, not a warning.
  bool noLoss = false;
  // POV-Ray: constructs outside the subset are warnings and are skipped
  // (sfconvert --skip-unsupported).
  bool skipUnsupported = false;
  // POV-Ray: the image size that image_width and image_height stand for;
  // 0 for sfrender's default, 640 x 480.
  int imageWidth = 0;
  int imageHeight = 0;
  // A larger input is refused unread (file-too-large); the tools check the
  // size before reading, and so do the readers of a glTF's external buffers.
  std::uint64_t maxFileSize = kDefaultMaxFileSize;
  // Reading stops at the first object or light past this (too-many-objects).
  std::size_t maxObjects = kDefaultMaxObjects;
  // glTF: more POSITION vertices than this in the file is gltf-too-large.
  std::size_t maxGltfVertices = kDefaultMaxGltfVertices;
  // glTF: more nodes and other objects (gltf::objectWeight) than this is
  // gltf-too-many-nodes, refused before tinygltf reads the file.
  std::size_t maxGltfNodes = kDefaultMaxGltfNodes;
};

// The scene and everything found while reading it. The scene is complete
// only when ok(); otherwise it holds the records that were read cleanly.
struct ReadResult {
  Scene scene;
  DiagnosticList diagnostics;

  bool ok() const { return !diagnostics.hasErrors(); }
};

}  // namespace scene
