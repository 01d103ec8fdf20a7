// The instruction file writer.
#pragma once

#include <optional>
#include <string>

#include "scenefile/diagnostic.h"
#include "scenefile/convert.h"
#include "scenefile/scene.h"

namespace scene {


// The scene as an instruction file: OUTPUT_FILE, the camera, the lights, then
// the objects with every material value. An object read from an instruction
// file keeps its operations; any other is decomposed into SCALE, ROTATE_X,
// ROTATE_Y, ROTATE_Z, TRANSLATE. Returns nothing, with the reasons in `out`,
// when the scene cannot be written as asked.
std::optional<std::string> writeInstructionFile(const Scene& scene,
                                                const ConversionOptions& options,
                                                DiagnosticList& out);

}  // namespace scene
