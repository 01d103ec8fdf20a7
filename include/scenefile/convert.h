/// @file
/// Converting a scene into any format, which may hold less than the scene
/// has, with every loss reported.
#pragma once

#include <optional>
#include <string>

#include "scenefile/diagnostic.h"
#include "scenefile/format.h"
#include "scenefile/options/gltf.h"
#include "scenefile/options/instruction_file.h"
#include "scenefile/options/obj.h"
#include "scenefile/options/pov.h"
#include "scenefile/scene.h"

namespace scene {

/// What a writer is told. `noLoss` applies to every format; each format's
/// own settings are in its member, and only its writer reads them.
struct ConversionOptions {
  /// Every loss is an error, and nothing is written.
  bool noLoss = false;
  /// Instruction files.
  InstructionWriteOptions instructions;
  /// glTF 2.0 (.gltf and .glb).
  GltfWriteOptions gltf;
  /// Wavefront OBJ (.obj and its .mtl).
  ObjWriteOptions obj;
  /// POV-Ray.
  PovWriteOptions pov;

  friend bool operator==(const ConversionOptions&, const ConversionOptions&) = default;
};

/// A conversion's files: the output, and for a .gltf whose buffer goes
/// beside it (GltfWriteOptions::externalBuffer) that buffer's bytes, for an
/// .obj its MTL file's (ObjWriteOptions::materialLibrary).
struct ConvertedFiles {
  /// The file itself: text, or bytes for a binary format.
  std::string main;
  /// The external buffer's or the MTL file's bytes, or empty.
  std::string sidecar;
};

/// The scene written in `format` as one file, or nothing when the conversion
/// cannot be done as asked. Each value the format cannot hold is reported in
/// `out` at the record it belongs to: a warning, or an error under `noLoss`.
/// A glTF buffer is embedded whatever options.gltf.externalBuffer says, and
/// an OBJ names no MTL file.
std::optional<std::string> convertScene(const Scene& scene, Format format,
                                        const ConversionOptions& options, DiagnosticList& out);

/// As convertScene, with a .gltf's buffer in a file of its own when
/// options.gltf.externalBuffer names one.
std::optional<ConvertedFiles> convertSceneToFiles(const Scene& scene, Format format,
                                                  const ConversionOptions& options,
                                                  DiagnosticList& out);

}  // namespace scene
