#include "libscene/conversion.h"

#include "libscene/instruction_writer.h"
#include "libscene/number.h"
#include "libscene/sf_writer.h"
#include "libscene/validation.h"

namespace scene {

namespace {

// A scene file holds only an object's colour: every other material value
// that is not the default is lost.
void reportMaterialLosses(const Scene& scene, Severity severity, DiagnosticList& out) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    for (MaterialProperty p : kMaterialProperties) {
      double value = materialValue(object.material, p);
      double fallback = defaultMaterialValue(p);
      if (value == fallback) continue;
      out.report(severity, DiagnosticCode::LossMaterial, object.span,
                 std::string(materialPropertyName(p)) + " " + formatNumber(value) + " of " +
                     std::string(objectKindName(object.kind)) + " object " +
                     std::to_string(i + 1) + " is dropped: a scene file keeps only the colour")
          .hint = "it becomes the default " + formatNumber(fallback);
    }
  }
}

}  // namespace

std::optional<std::string> convertScene(const Scene& scene, OutputFormat format,
                                        const ConversionOptions& options, DiagnosticList& out) {
  // Checked once here, so that no writer is ever given a NaN or an infinity,
  // whatever built the scene.
  if (!checkSceneFinite(scene, out)) return std::nullopt;
  switch (format) {
    case OutputFormat::SceneFile: {
      std::size_t errorsBefore = out.errorCount();
      reportMaterialLosses(scene, options.noLoss ? Severity::Error : Severity::Warning, out);
      if (scene.outputFile) {
        out.note(DiagnosticCode::DroppedOutputFile, scene.outputFileSpan,
                 "OUTPUT_FILE is not written: a scene file names no output")
            .hint = "sfrender takes the output name with -o";
      }
      if (out.errorCount() != errorsBefore) return std::nullopt;
      return writeSceneFile(scene);
    }
    case OutputFormat::InstructionFile: {
      InstructionWriteOptions writeOptions;
      writeOptions.approximate = options.approximate;
      writeOptions.noLoss = options.noLoss;
      writeOptions.outputFile = options.outputFile;
      return writeInstructionFile(scene, writeOptions, out);
    }
    case OutputFormat::Gltf:
    case OutputFormat::Glb: {
      GltfWriteOptions writeOptions = options.gltf;
      writeOptions.binary = format == OutputFormat::Glb;
      writeOptions.noLoss = options.noLoss;
      // One string holds one file: the buffer is embedded.
      writeOptions.externalBuffer.clear();
      std::optional<GltfFiles> files = writeGltf(scene, writeOptions, out);
      if (!files) return std::nullopt;
      return std::move(files->main);
    }
    case OutputFormat::Pov: {
      PovWriteOptions writeOptions = options.pov;
      writeOptions.noLoss = options.noLoss;
      return writePovScene(scene, writeOptions, out);
    }
  }
  return std::nullopt;
}

std::optional<ConvertedFiles> convertSceneToFiles(const Scene& scene, OutputFormat format,
                                                  const ConversionOptions& options,
                                                  DiagnosticList& out) {
  if (format == OutputFormat::Gltf && !options.gltf.externalBuffer.empty()) {
    if (!checkSceneFinite(scene, out)) return std::nullopt;
    GltfWriteOptions writeOptions = options.gltf;
    writeOptions.binary = false;
    writeOptions.noLoss = options.noLoss;
    std::optional<GltfFiles> files = writeGltf(scene, writeOptions, out);
    if (!files) return std::nullopt;
    return ConvertedFiles{std::move(files->main), std::move(files->buffer)};
  }
  std::optional<std::string> text = convertScene(scene, format, options, out);
  if (!text) return std::nullopt;
  return ConvertedFiles{std::move(*text), {}};
}

}  // namespace scene
