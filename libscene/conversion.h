// Converting a scene into a format that may hold less than the scene has,
// with every loss reported.
#pragma once

#include <optional>
#include <string>

#include "libscene/diagnostic.h"
#include "libscene/scene.h"

namespace scene {

enum class OutputFormat { SceneFile, InstructionFile };

struct ConversionOptions {
  // Every loss is an error, and nothing is written.
  bool noLoss = false;
  // Write the nearest expressible form where the exact one does not exist.
  bool approximate = false;
  // OUTPUT_FILE for an instruction file made from a scene that has none.
  std::string outputFile = "output.ppm";
};

// The scene's text in `format`, or nothing when the conversion cannot be
// done as asked. Each value the format cannot hold is reported in `out` at
// the record it belongs to: a warning, or an error under `noLoss`.
std::optional<std::string> convertScene(const Scene& scene, OutputFormat format,
                                        const ConversionOptions& options, DiagnosticList& out);

}  // namespace scene
