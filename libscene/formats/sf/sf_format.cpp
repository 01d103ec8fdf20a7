// The scene file's row of the format registry.
#include <string_view>

#include "libscene/formats/format_rows.h"
#include "libscene/formats/sf/sf_layout.h"
#include "libscene/formats/sf/sf_outline.h"
#include "libscene/formats/sf/sf_reader.h"
#include "libscene/formats/sf/sf_writer.h"
#include "libscene/text/number.h"
#include "libscene/text/text_lines.h"
#include "scenefile/convert.h"
#include "scenefile/outline.h"

namespace scene {
namespace {

constexpr std::string_view kSfExtensions[] = {".sf"};

// A scene file starts with a record name; one whose names are misspelt or in
// lower case is still a scene file, whose reader says what is wrong with
// better words than "unknown format". An empty file is a scene file too.
Recognition recogniseSceneFile(std::string_view text) {
  std::optional<std::string_view> first = firstWordOutsideComments(text);
  if (!first) return Recognition::Default;
  for (std::string_view name : sceneFileRecordNames()) {
    if (startsWithIgnoringCase(*first, name.substr(0, 3))) return Recognition::Likely;
  }
  return Recognition::None;
}

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
                     std::string(objectKindName(object.kind)) + " object " + std::to_string(i + 1) +
                     " is dropped: a scene file keeps only the colour")
          .hint = "it becomes the default " + formatNumber(fallback);
    }
  }
}

std::optional<ConvertedFiles> writeSceneFileFormat(const Scene& scene,
                                                   const ConversionOptions& options,
                                                   DiagnosticList& out) {
  std::size_t errorsBefore = out.errorCount();
  reportMaterialLosses(scene, options.noLoss ? Severity::Error : Severity::Warning, out);
  if (scene.outputFile) {
    Diagnostic& d = out.note(DiagnosticCode::DroppedOutputFile, scene.outputFileSpan,
                             "OUTPUT_FILE is not written: a scene file names no output");
    d.hint = "the image's name is then given when rendering ({0})";
    d.remedies = {{Setting::OutputPath, *scene.outputFile}};
  }
  if (out.errorCount() != errorsBefore) return std::nullopt;
  return ConvertedFiles{writeSceneFile(scene), {}};
}

ReadResult readSceneFileFormat(std::string_view text, std::string fileName,
                               const ReadOptions& options) {
  return parseSceneFile(text, std::move(fileName), options);
}

}  // namespace

FormatInfo sceneFileFormat() {
  FormatInfo row;
  row.format = Format::SceneFile;
  row.name = "sf";
  row.singular = "a scene file";
  row.plural = "scene files";
  row.extensions = kSfExtensions;
  row.startsWith = "a CAMERA record";
  row.recognise = recogniseSceneFile;
  row.read = readSceneFileFormat;
  row.outline = sceneFileOutline;
  row.place = sceneFilePlace;
  row.layout = sceneFileLayout;
  row.write = writeSceneFileFormat;
  return row;
}

}  // namespace scene
