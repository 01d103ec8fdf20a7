// The scene file (.sf) reader: six-line records, CAMERA first.
#pragma once

#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace scene {

// Reads a whole scene file from memory and reports every problem it finds,
// recovering at the next record. `fileName` goes into the diagnostics.
ReadResult parseSceneFile(std::string_view text, std::string fileName,
                          const ReadOptions& options = {});

}  // namespace scene
