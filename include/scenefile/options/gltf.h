/// @file
/// What reading and writing glTF 2.0 (.gltf, .glb) can be told beyond the
/// common options.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace scene {

/// The default limit on POSITION vertices read from one glTF file, all meshes
/// together; indices are held to three times as many.
inline constexpr std::size_t kDefaultMaxGltfVertices = std::size_t{1} << 24;
/// The default limit on nodes and every other glTF object (docs/GLTF.md,
/// "Hostile files"): tinygltf holds each in hundreds of bytes, however few
/// the file spends.
inline constexpr std::size_t kDefaultMaxGltfNodes = 1'000'000;

/// Options of the glTF reader.
struct GltfReadOptions {
  /// More POSITION vertices than this in the file is gltf-too-large.
  std::size_t maxVertices = kDefaultMaxGltfVertices;
  /// More nodes and other objects than this is gltf-too-many-nodes, refused
  /// before the file is parsed (Setting::MaxGltfNodes).
  std::size_t maxNodes = kDefaultMaxGltfNodes;

  friend bool operator==(const GltfReadOptions&, const GltfReadOptions&) = default;
};

/// How a viewer makes a glTF point light fall off, which the writer's light
/// intensities are made for.
enum class GltfLightFalloff {
  /// With the square of the distance, in candela (glTF's definition;
  /// Blender, three.js): each light is matched at a reference distance.
  InverseSquare,
  /// Not at all, the intensity a plain factor (f3d 1.3, VTK): each light's
  /// intensity is the largest channel of its COLOUR, as a scene file's
  /// LIGHT, which does not fall off either.
  None,
};

/// Options of the glTF writer. Whether the output is JSON text or a .glb is
/// the format written (Format::Gltf or Format::Glb), not an option.
struct GltfWriteOptions {
  /// For JSON text: the name of a buffer file to write beside it (its URI);
  /// empty embeds the buffer as base64.
  std::string externalBuffer;
  /// The camera's vertical field of view in degrees; unset takes the
  /// scene's View, and 60 for a scene without one.
  std::optional<double> yfovDegrees;
  /// The image size, for the camera's aspect ratio; 0 takes the scene's
  /// View's aspect ratio, or leaves it out.
  int width = 0;
  int height = 0;
  /// How finely curved surfaces are tessellated (scenefile/mesh.h).
  int segments = 32;
  /// Whether the lights are written (KHR_lights_punctual); false leaves
  /// them out, each reported (gltf-light-left-out), for readers that refuse
  /// the extension (assimp 5.2).
  bool lights = true;
  /// Whether the exact values ride in `extras` (docs/GLTF.md, "Extras");
  /// false leaves every one out, reported once (gltf-extras-left-out), for
  /// readers that cannot copy object or array extras (assimp 5.2's export):
  /// the file then reads back by mesh fitting.
  bool extras = true;
  /// How the lights are scaled (docs/GLTF.md, "Lights").
  GltfLightFalloff lightFalloff = GltfLightFalloff::InverseSquare;
  /// The asset's generator string.
  std::string generator = "scenefile";

  friend bool operator==(const GltfWriteOptions&, const GltfWriteOptions&) = default;
};

}  // namespace scene
