// Ctrl+S and Ctrl+O: the scene saved under a name the user types, in the
// format its extension names (the library's format registry and writers),
// and a file of any format the suite reads opened as the scene.
#pragma once

#include <string>

#include "tools/sfbuild/builder_state.h"

namespace sfbuild {

// Writes the scene to `name` in the format of its extension: .sf a scene
// file, .txt an instruction file (which keeps the materials), and .gltf,
// .glb, .pov as sfconvert writes them. A name with no such extension, or
// an existing file other than state.currentFile, is refused. Says what
// happened in state.lastSave ("saved NAME" or why not); true once written.
bool saveSceneAs(BuilderState& state, const std::string& name, const FileSystem& files);

// Reads `name` (its format recognised from its content, as sfrender does)
// and makes it the scene, camera included: one step of the history, so
// that Ctrl+Z gives the scene before back. On failure the scene stays and
// state.lastSave says why, the first error at its file:line:column.
bool openSceneFile(BuilderState& state, const std::string& name, const FileSystem& files);

}  // namespace sfbuild
