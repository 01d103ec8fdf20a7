// The OBJ reader: each group (`o` or `g`) with faces becomes one object,
// exactly as its exact-value comment says while its mesh and material are
// still what the writer wrote for it, else the primitive that the mesh
// fitting (scenefile/mesh_fit.h) recognises in it, as the glTF reader does
// (docs/OBJ.md, "Reading").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace scene {

// Reads `text`. The MTL files it names are read from `folder` only (plain
// names, regular files, options.maxFileSize at most); with no folder none
// is read.
ReadResult parseObj(std::string_view text, std::string fileName,
                    const std::optional<std::filesystem::path>& folder,
                    const ReadOptions& options = {});

}  // namespace scene
