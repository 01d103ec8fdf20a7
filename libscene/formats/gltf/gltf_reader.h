// The glTF 2.0 reader (.gltf and .glb), through tinygltf, with every index,
// size and count checked before it is used.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace scene {

// Limits that keep a hostile file from costing unbounded memory or time;
// the size of the file and of each buffer is ReadOptions::maxFileSize, the
// vertices ReadOptions::maxGltfVertices.
inline constexpr int kMaxJsonDepth = 64;

// `bytes` starts with the GLB magic, or (after blanks) with '{'.
bool looksLikeGlb(std::string_view bytes);
bool looksLikeGltfJson(std::string_view bytes);

// Reads a .gltf or .glb held in memory. External buffers are read from
// `folder` (the glTF's own folder) and never from anywhere else; images are
// never read or decoded. Objects come from our own `extras` when they still
// match the nodes, else from fitting each mesh (mesh_fit.h); the hierarchy
// of the default scene is flattened into world matrices. Every loss is
// reported: a warning, or an error under options.noLoss.
ReadResult parseGltf(std::string_view bytes, std::string fileName,
                     const std::filesystem::path& folder, const ReadOptions& options = {});

}  // namespace scene
