// The instruction file writer.
#pragma once

#include <optional>
#include <string>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

struct InstructionWriteOptions {
  // Write the nearest expressible form of a matrix with shear or a rolled
  // camera, and report how far each value moved, instead of failing.
  bool approximate = false;
  // Treat an approximation as an error even when `approximate` is set.
  bool noLoss = false;
  // OUTPUT_FILE for a scene that has none (one read from a scene file).
  std::string outputFile = "output.ppm";
};

// The scene as an instruction file: OUTPUT_FILE, the camera, the lights, then
// the objects with every material value. An object read from an instruction
// file keeps its operations; any other is decomposed into SCALE, ROTATE_X,
// ROTATE_Y, ROTATE_Z, TRANSLATE. Returns nothing, with the reasons in `out`,
// when the scene cannot be written as asked.
std::optional<std::string> writeInstructionFile(const Scene& scene,
                                                const InstructionWriteOptions& options,
                                                DiagnosticList& out);

}  // namespace scene
