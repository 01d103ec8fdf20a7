// Reading a scene whose format is recognised from its content.
#pragma once

#include <cstdint>
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

// Reports file-too-large when an input of `bytes` bytes is above
// options.maxFileSize; true when it is within the limit. The tools call it
// with the size on disk before reading, parseScene with the text's size.
bool checkFileSize(std::uint64_t bytes, const ReadOptions& options, DiagnosticList& out);

// Detects the format and reads with the matching reader; text in no known
// format gets an unknown-format error, text above options.maxFileSize
// file-too-large. A glTF file's external buffers are looked for in the
// folder of `fileName`.
ReadResult parseScene(std::string_view text, std::string fileName,
                      const ReadOptions& options = {});

}  // namespace scene
