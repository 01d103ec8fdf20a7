// Converting a scene into a format that may hold less than the scene has,
// with every loss reported.
#pragma once

#include <optional>
#include <string>

#include "libscene/diagnostic.h"
#include "libscene/gltf_writer.h"
#include "libscene/pov_writer.h"
#include "libscene/scene.h"

namespace scene {

enum class OutputFormat { SceneFile, InstructionFile, Gltf, Glb, Pov };

struct ConversionOptions {
  // Every loss is an error, and nothing is written.
  bool noLoss = false;
  // Write the nearest expressible form where the exact one does not exist.
  bool approximate = false;
  // OUTPUT_FILE for an instruction file made from a scene that has none.
  std::string outputFile = "output.ppm";
  // For glTF output: the camera's field of view, the image size, the
  // tessellation and where the buffer goes (GltfWriteOptions; `binary` and
  // `noLoss` follow the format and the option above).
  GltfWriteOptions gltf;
  // For POV-Ray output: the sfrender settings to match, and --flat
  // (`noLoss` follows the option above).
  PovWriteOptions pov;
};

// The scene's text in `format`, or nothing when the conversion cannot be
// done as asked. Each value the format cannot hold is reported in `out` at
// the record it belongs to: a warning, or an error under `noLoss`.
std::optional<std::string> convertScene(const Scene& scene, OutputFormat format,
                                        const ConversionOptions& options, DiagnosticList& out);

// A conversion's files: the output, and for a .gltf whose buffer goes
// beside it (options.gltf.externalBuffer), that buffer's bytes.
struct ConvertedFiles {
  std::string main;
  std::string sidecar;
};
std::optional<ConvertedFiles> convertSceneToFiles(const Scene& scene, OutputFormat format,
                                                  const ConversionOptions& options,
                                                  DiagnosticList& out);

}  // namespace scene
