// The instruction file reader: OUTPUT_FILE, then CAMERA, LIGHT and OBJECT
// blocks with their MATERIAL and TRANSFORMATION sections.
#pragma once

#include <string>
#include <string_view>

#include "scenefile/read.h"

namespace scene {

// Reads a whole instruction file from memory and reports every problem it
// finds, recovering at the next line or block. Object matrices are composed
// from the operations (composeTransform); the operations are kept too.
ReadResult parseInstructionFile(std::string_view text, std::string fileName,
                                const ReadOptions& options = {});

}  // namespace scene
