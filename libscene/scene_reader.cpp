#include "libscene/scene_reader.h"

#include <cctype>
#include <filesystem>

#include "libscene/gltf_reader.h"
#include "libscene/instruction_reader.h"
#include "libscene/pov_reader.h"
#include "libscene/sf_reader.h"
#include "libscene/text_lines.h"
#include "libscene/validation.h"

namespace scene {

namespace {

bool startsWithIgnoringCase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  }
  return true;
}

}  // namespace

SceneFormat detectFormat(std::string_view text, std::string_view fileName) {
  if (looksLikeGlb(text)) return SceneFormat::Glb;
  if (looksLikeGltfJson(text)) return SceneFormat::Gltf;
  if (looksLikePov(text)) return SceneFormat::Pov;
  // The extension decides only what the content leaves open.
  bool povName = fileName.ends_with(".pov");
  LineCursor cursor(text);
  while (cursor.next()) {
    if (cursor.blank()) continue;
    std::string_view first = cursor.token(0).text;
    // Comments are errors in both formats, which the reader reports; they
    // say nothing about which format this is.
    if (first.starts_with("#") || first.starts_with("//")) continue;
    if (first == "OUTPUT_FILE" || first == "START" || first == "END") {
      return SceneFormat::InstructionFile;
    }
    // A scene file whose names are misspelt or in lower case is still a
    // scene file: its reader says what is wrong with better words.
    for (std::string_view name : {"CAMERA", "LIGHT", "PLANE", "SPHERE", "CYLINDER", "CUBE"}) {
      if (startsWithIgnoringCase(first, name.substr(0, 3))) return SceneFormat::SceneFile;
    }
    if (startsWithIgnoringCase(first, "OUTPUT") || startsWithIgnoringCase(first, "START")) {
      return SceneFormat::InstructionFile;
    }
    return povName ? SceneFormat::Pov : SceneFormat::Unknown;
  }
  return povName ? SceneFormat::Pov : SceneFormat::SceneFile;
}

bool checkFileSize(std::uint64_t bytes, const ReadOptions& options, DiagnosticList& out) {
  if (bytes <= options.maxFileSize) return true;
  out.error(DiagnosticCode::FileTooLarge, {},
            "the file is " + std::to_string(bytes) + " bytes, more than the limit of " +
                std::to_string(options.maxFileSize))
      .hint = "raise the limit with --max-file-size if the file is meant to be this large";
  return false;
}

namespace {

ReadResult readInDetectedFormat(std::string_view text, std::string fileName,
                                const ReadOptions& options);

}  // namespace

ReadResult parseScene(std::string_view text, std::string fileName, const ReadOptions& options) {
  ReadResult result = readInDetectedFormat(text, std::move(fileName), options);
  // The readers report a value that is not finite where it was made; this is
  // the last line, so that no accepted scene holds one whatever a reader missed.
  if (result.ok()) checkSceneFinite(result.scene, result.diagnostics);
  return result;
}

namespace {

ReadResult readInDetectedFormat(std::string_view text, std::string fileName,
                                const ReadOptions& options) {
  if (text.size() > options.maxFileSize) {
    ReadResult refused{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
    checkFileSize(text.size(), options, refused.diagnostics);
    return refused;
  }
  switch (detectFormat(text, fileName)) {
    case SceneFormat::SceneFile:
      return parseSceneFile(text, std::move(fileName), options);
    case SceneFormat::InstructionFile:
      return parseInstructionFile(text, std::move(fileName), options);
    case SceneFormat::Gltf:
    case SceneFormat::Glb: {
      std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
      return parseGltf(text, std::move(fileName), folder, options);
    }
    case SceneFormat::Pov: {
      PovReadOptions povOptions;
      povOptions.skipUnsupported = options.skipUnsupported;
      povOptions.noLoss = options.noLoss;
      if (options.imageWidth > 0 && options.imageHeight > 0) {
        povOptions.imageWidth = options.imageWidth;
        povOptions.imageHeight = options.imageHeight;
      }
      povOptions.errorLimit = options.errorLimit;
      povOptions.maxObjects = options.maxObjects;
      return importPov(text, std::move(fileName), povOptions).read;
    }
    case SceneFormat::Unknown:
      break;
  }
  ReadResult result{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
  LineCursor cursor(text);
  SourceSpan where{1, 1, 0};
  while (cursor.next()) {
    if (!cursor.blank()) {
      where = cursor.tokenSpan(0);
      break;
    }
  }
  result.diagnostics
      .error(DiagnosticCode::UnknownFormat, where,
             "not a scene file or an instruction file")
      .hint =
      "a scene file starts with a CAMERA record, an instruction file with OUTPUT_FILE";
  return result;
}

}  // namespace

}  // namespace scene
