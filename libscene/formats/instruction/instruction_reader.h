// The instruction file reader: OUTPUT_FILE, then CAMERA, LIGHT and OBJECT
// blocks with their MATERIAL and TRANSFORMATION sections.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/read.h"

namespace scene {

// Reads a whole instruction file from memory and reports every problem it
// finds, recovering at the next line or block. Object matrices are composed
// from the operations (composeTransform); the operations are kept too.
ReadResult parseInstructionFile(std::string_view text, std::string fileName,
                                const ReadOptions& options = {});

// The block names: CAMERA, LIGHT, OBJECT, MATERIAL, TRANSFORMATION.
std::span<const std::string_view> instructionBlockNames();

// Every keyword a line may start with.
std::span<const std::string_view> instructionLineKeywords();

// A property: its keyword, the name of the block it belongs in and how many
// numbers it takes.
struct InstructionProperty {
  std::string_view keyword;
  std::string_view block;
  int count = 0;
};
std::vector<InstructionProperty> instructionProperties();

}  // namespace scene
