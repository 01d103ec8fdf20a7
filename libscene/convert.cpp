// Converting a scene to any format, through the format registry.
#include "scenefile/convert.h"

#include <string>

#include "scenefile/validation.h"

namespace scene {

namespace {

// The views that the scene and the writers' options (a field of view, an
// image size for the aspect ratio) give, each held to checkView; true when
// all are in range.
bool viewsInRange(const Scene& scene, const ConversionOptions& options, DiagnosticList& out) {
  std::size_t errors = out.errorCount();
  if (scene.view) checkView(*scene.view, scene.view->span, out);
  struct Asked {
    std::optional<double> fov;
    int width, height;
  };
  for (const Asked& asked :
       {Asked{options.gltf.yfovDegrees, options.gltf.width, options.gltf.height},
        Asked{options.pov.verticalFovDegrees, options.pov.width, options.pov.height}}) {
    // A side of 0 is left to the scene's view.
    if (asked.width < 0 || asked.height < 0 || asked.width > kMaxImageSide ||
        asked.height > kMaxImageSide) {
      out.error(DiagnosticCode::ValueOutOfRange, {},
                "the image size " + std::to_string(asked.width) + "x" +
                    std::to_string(asked.height) + " is outside 1 to " +
                    std::to_string(kMaxImageSide) + " pixels a side");
    }
    View view;
    if (asked.fov) view.verticalFovDegrees = *asked.fov;
    if (asked.width > 0 && asked.height > 0) {
      view.aspectRatio = static_cast<double>(asked.width) / asked.height;
    }
    checkView(view, {}, out);
  }
  return out.errorCount() == errors;
}

}  // namespace

std::optional<ConvertedFiles> convertSceneToFiles(const Scene& scene, Format format,
                                                  const ConversionOptions& options,
                                                  DiagnosticList& out) {
  // Checked once here, so that no writer is ever given a NaN or an infinity
  // or a view out of range, whatever built the scene.
  if (!checkSceneFinite(scene, out) || !viewsInRange(scene, options, out)) return std::nullopt;
  return formatInfo(format).write(scene, options, out);
}

std::optional<std::string> convertScene(const Scene& scene, Format format,
                                        const ConversionOptions& options, DiagnosticList& out) {
  // One string holds one file: the buffer is embedded.
  std::optional<ConvertedFiles> files;
  if (!options.gltf.externalBuffer.empty() || !options.obj.materialLibrary.empty()) {
    ConversionOptions embedded = options;
    embedded.gltf.externalBuffer.clear();
    embedded.obj.materialLibrary.clear();
    files = convertSceneToFiles(scene, format, embedded, out);
  } else {
    files = convertSceneToFiles(scene, format, options, out);
  }
  if (!files) return std::nullopt;
  return std::move(files->main);
}

}  // namespace scene
