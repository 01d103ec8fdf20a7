#include "libscene/formats/gltf/gltf_reader.h"

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <utility>

#include "libscene/formats/gltf/glb.h"
#include "libscene/formats/gltf/gltf_document.h"
#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_files.h"
#include "libscene/formats/gltf/gltf_import.h"
#include "libscene/formats/gltf/gltf_json_scan.h"
#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"
#include "scenefile/read.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// Extensions whose absence from our reading changes nothing a scene file
// can hold; a file that requires any other cannot be read right.
const std::set<std::string> kReadableRequired = {
    "KHR_lights_punctual",    "KHR_materials_ior",       "KHR_materials_transmission",
    "KHR_materials_specular", "KHR_texture_transform",   "KHR_materials_emissive_strength",
    "KHR_materials_unlit",    "EXT_mesh_gpu_instancing",
};

// ---------------------------------------------------------------------------
// The text before tinygltf sees it.

// nlohmann's message without its "[json.exception...] parse error at line
// L, column C: " prefix, which the span already says.
std::string parseErrorMessage(const std::string& what) {
  std::size_t colon = what.find(": ");
  std::string message = colon == std::string::npos ? what : what.substr(colon + 2);
  return message;
}

// Whether the file's weighted count of objects (gltf::objectWeight) is
// within options.gltf.maxNodes; when not, says so.
bool withinObjectLimit(std::size_t objects, const ReadOptions& options, DiagnosticList& out) {
  if (objects <= options.gltf.maxNodes) return true;
  Diagnostic& d =
      out.error(DiagnosticCode::GltfTooManyNodes, {},
                "the file has " + std::to_string(objects) +
                    " nodes and other objects (a material counting 5, a camera or a light 2), more "
                    "than the limit of " +
                    std::to_string(options.gltf.maxNodes));
  d.hint = "raise the limit with {0} if the file is meant to be this large";
  d.remedies = {{Setting::MaxGltfNodes, std::to_string(objects)}};
  return false;
}

// The JSON of a .gltf (without its byte order mark) or of a GLB's JSON
// chunk, with the GLB's BIN chunk.
struct JsonText {
  std::string_view bytes;  // the whole file
  std::string_view json;
  std::optional<std::string_view> bin;
  bool binary = false;

  // Where the JSON starts in the file.
  std::size_t offset() const { return bytes.size() - json.size(); }
  // The text in which spans are counted: the file, or none for a GLB, whose
  // JSON has no lines a person reads.
  std::string_view spanText() const { return binary ? std::string_view{} : bytes; }
  // Where byte `byte` of the JSON is in the file.
  SourceSpan span(std::size_t byte) const {
    return binary ? SourceSpan{} : LineColumnCounter(bytes).at(byte + offset());
  }
};

std::optional<JsonText> findJson(std::string_view bytes, DiagnosticList& out) {
  JsonText text{bytes, bytes, std::nullopt, looksLikeGlb(bytes)};
  if (text.binary) {
    std::string why;
    std::optional<GlbChunks> chunks = decodeGlb(bytes, why);
    if (!chunks) {
      out.error(DiagnosticCode::GltfInvalidGlb, {}, "not a valid GLB file: " + why);
      return std::nullopt;
    }
    text.json = chunks->json;
    text.bin = chunks->bin;
  } else if (text.json.starts_with("\xEF\xBB\xBF")) {
    text.json.remove_prefix(3);
  }
  return text;
}

// The JSON document, once its depth and its count of objects are known to
// be within the limits: both are read from the bytes (gltf_json_scan.h),
// before anything is parsed, as a node costs three bytes of text and
// hundreds in memory.
std::optional<Json> parseJson(const JsonText& text, const ReadOptions& options,
                              DiagnosticList& out) {
  gltf::JsonScan scan = gltf::scanJson(text.json, kMaxJsonDepth);
  if (scan.tooDeepAt) {
    out.error(DiagnosticCode::GltfInvalidJson, text.span(*scan.tooDeepAt),
              "the JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return std::nullopt;
  }
  if (!withinObjectLimit(scan.objects, options, out)) return std::nullopt;
  std::string notJson =
      text.binary ? "the GLB's JSON chunk is not valid JSON: " : "not valid JSON: ";
  try {
    return Json::parse(text.json);
  } catch (const Json::parse_error& e) {
    std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    out.error(DiagnosticCode::GltfInvalidJson, text.span(at),
              notJson + parseErrorMessage(e.what()));
  } catch (const Json::out_of_range& e) {
    // A number past a double's range (1e400) is refused by nlohmann as
    // out_of_range, not as a parse error, and carries no position.
    std::string what = e.what();
    std::size_t bracket = what.find("] ");
    out.error(DiagnosticCode::GltfInvalidJson, {},
              notJson + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
  return std::nullopt;
}

// glTF 2.0 only: an object with a string asset.version of 2.x.
bool isGltf2(const Json& doc, DiagnosticList& out) {
  if (!doc.is_object()) {
    out.error(DiagnosticCode::GltfInvalid, {}, "the JSON is not an object, so it is no glTF");
    return false;
  }
  const Json* asset = doc.contains("asset") && doc["asset"].is_object() ? &doc["asset"] : nullptr;
  if (!asset || !asset->contains("version") || !(*asset)["version"].is_string()) {
    out.error(DiagnosticCode::GltfInvalid, {}, "the file has no asset.version, so it is no glTF");
    return false;
  }
  std::string version = (*asset)["version"].get<std::string>();
  if (!version.starts_with("2.")) {
    out.error(DiagnosticCode::GltfInvalid, {},
              "asset.version is '" + version + "'; only glTF 2.0 is read");
    return false;
  }
  return true;
}

void checkRequiredExtensions(const Json& doc, DiagnosticList& out) {
  if (!doc.contains("extensionsRequired") || !doc["extensionsRequired"].is_array()) return;
  for (const Json& name : doc["extensionsRequired"]) {
    if (name.is_string() && !kReadableRequired.count(name.get<std::string>())) {
      out.error(
          DiagnosticCode::GltfUnsupportedExtension, {},
          "the file requires the extension " + name.get<std::string>() + ", which is not read");
    }
  }
}

// The OUTPUT file that our own extras of the asset name, if they do.
std::optional<std::string> outputFileOf(const Json& doc) {
  const Json& asset = doc["asset"];
  if (!asset.contains("extras")) return std::nullopt;
  const Json* sf = gltf::sfExtras(asset["extras"]);
  if (sf && sf->contains("outputFile") && (*sf)["outputFile"].is_string()) {
    return (*sf)["outputFile"].get<std::string>();
  }
  return std::nullopt;
}

// Everything of the document that is checked before tinygltf reads it:
// its values (gltf_document.h), the extensions it requires and the files
// it names. False when an error was found.
bool checkBeforeLoading(const Json& doc, const JsonText& text, const fs::path& folder,
                        const ReadOptions& options, DiagnosticList& out) {
  if (!withinObjectLimit(gltf::countObjects(doc), options, out)) return false;
  gltf::reportProblems(gltf::checkDocument(doc, options.noLoss), text.spanText(), text.offset(),
                       out);
  if (out.hasErrors()) return false;
  checkRequiredExtensions(doc, out);
  if (out.hasErrors()) return false;
  gltf::checkBufferFiles(doc, folder, options, out);
  return !out.hasErrors();
}

}  // namespace

bool looksLikeGlb(std::string_view bytes) {
  return bytes.starts_with(kGlbMagic);
}

bool looksLikeGltfJson(std::string_view bytes) {
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
  for (char c : bytes) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
    return c == '{';
  }
  return false;
}

ReadResult parseGltf(std::string_view bytes, std::string fileName, const fs::path& folder,
                     const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(fileName, options.errorLimit)};
  DiagnosticList& out = result.diagnostics;
  if (!checkFileSize(bytes.size(), options, out)) return result;
  std::optional<JsonText> text = findJson(bytes, out);
  if (!text) return result;
  std::optional<Json> doc = parseJson(*text, options, out);
  if (!doc || !isGltf2(*doc, out) || !checkBeforeLoading(*doc, *text, folder, options, out)) {
    return result;
  }
  std::optional<std::string> outputFile = outputFileOf(*doc);
  // Images are never needed: tinygltf does not even see them, nor any
  // extras or extension that is not read; the document is let go before
  // tinygltf parses its own.
  doc->erase("images");
  gltf::OwnExtras own = gltf::trimForTinygltf(*doc);
  std::string cleaned = doc->dump();
  doc.reset();

  tinygltf::Model model;
  if (!gltf::loadModel(cleaned, text->bin, text->binary, folder, options.maxFileSize, model, out)) {
    return result;
  }
  gltf::Importer importer(model, own, options, result);
  importer.run();
  if (out.hasErrors()) return result;
  // What the file gave must hold as a scene file's values would, and its
  // OUTPUT_FILE as an instruction file's.
  if (outputFile) result.scene.outputFile = *outputFile;
  DiagnosticList checked = validateScene(result.scene, fileName);
  out.append(checked);
  return result;
}

}  // namespace scene
