// Reading a scene whose format is recognised from its content.
#pragma once

#include <string>
#include <string_view>

#include "libscene/read_result.h"

namespace scene {

enum class SceneFormat { SceneFile, InstructionFile, Unknown, Gltf, Glb, Pov };

// An instruction file starts with OUTPUT_FILE (or, missing it, START); a
// scene file with a record name; an empty file counts as a scene file. glTF
// starts with '{', binary glTF with the magic "glTF". POV-Ray's language is
// recognised by its syntax (looksLikePov); a file named .pov whose content
// says nothing else (empty, comments only, or unknown) is read as POV-Ray.
SceneFormat detectFormat(std::string_view text, std::string_view fileName = {});

// Detects the format and reads with the matching reader; text in no known
// format gets an unknown-format error. A glTF file's external buffers are
// looked for in the folder of `fileName`.
ReadResult parseScene(std::string_view text, std::string fileName,
                      const ReadOptions& options = {});

}  // namespace scene
