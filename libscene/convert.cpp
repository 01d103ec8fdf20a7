// Converting a scene to any format, through the format registry.
#include "scenefile/convert.h"

#include "scenefile/validation.h"

namespace scene {

std::optional<ConvertedFiles> convertSceneToFiles(const Scene& scene, Format format,
                                                  const ConversionOptions& options,
                                                  DiagnosticList& out) {
  // Checked once here, so that no writer is ever given a NaN or an infinity,
  // whatever built the scene.
  if (!checkSceneFinite(scene, out)) return std::nullopt;
  return formatInfo(format).write(scene, options, out);
}

std::optional<std::string> convertScene(const Scene& scene, Format format,
                                        const ConversionOptions& options, DiagnosticList& out) {
  // One string holds one file: the buffer is embedded.
  std::optional<ConvertedFiles> files;
  if (!options.gltf.externalBuffer.empty()) {
    ConversionOptions embedded = options;
    embedded.gltf.externalBuffer.clear();
    files = convertSceneToFiles(scene, format, embedded, out);
  } else {
    files = convertSceneToFiles(scene, format, options, out);
  }
  if (!files) return std::nullopt;
  return std::move(files->main);
}

}  // namespace scene
