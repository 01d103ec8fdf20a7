// Reading a scene whose format is recognised from its content.
#pragma once

#include <string>
#include <string_view>

#include "libscene/read_result.h"

namespace scene {

enum class SceneFormat { SceneFile, InstructionFile, Unknown };

// An instruction file starts with OUTPUT_FILE (or, missing it, START); a
// scene file with a record name; an empty file counts as a scene file.
SceneFormat detectFormat(std::string_view text);

// Detects the format and reads with the matching reader; text in neither
// format gets an unknown-format error.
ReadResult parseScene(std::string_view text, std::string fileName,
                      const ReadOptions& options = {});

}  // namespace scene
