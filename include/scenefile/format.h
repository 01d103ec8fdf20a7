/// @file
/// The format registry: one row per file format, from which detection, the
/// tools' format names and help texts, and the conversions all come.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace scene {

class DiagnosticList;
struct Scene;
struct ReadOptions;
struct ReadResult;
struct ConversionOptions;
struct ConvertedFiles;
struct Outline;
struct TextPlace;

/// A file format of the suite (scenefile/formats.def lists them).
enum class Format : std::uint8_t {
#define SCENEFILE_FORMAT(enumerator, name, folder, row) enumerator,
#include "scenefile/formats.def"
#undef SCENEFILE_FORMAT
};

/// How sure a format is that some bytes are written in it.
enum class Recognition : std::uint8_t {
  /// Not this format.
  None,
  /// The bytes say nothing (blanks and comments only), and this format reads
  /// such a file: chosen only when no format recognises more.
  Default,
  /// The first word is this format's: chosen when no format is certain.
  Likely,
  /// A signature only this format has (a magic number, a syntax).
  Certain,
};

/// What a format can hold of the scene model beyond the camera, the lights,
/// and each object's kind, colour and matrix.
struct FormatHolds {
  /// The Phong values other than the colour.
  bool materials = false;
  /// An object's list of SCALE, TRANSLATE and ROTATE operations as written.
  bool transformLists = false;
  /// An instruction file's OUTPUT_FILE.
  bool outputFile = false;
  /// The field of view and the aspect ratio (Scene::view).
  bool view = false;
};

/// One row of the registry.
struct FormatInfo {
  /// The format this row describes.
  Format format = Format::SceneFile;
  /// The format's name, as the tools and Python take it: "sf", "instructions", ...
  std::string_view name;
  /// The format with its article, for messages: "a scene file".
  std::string_view singular;
  /// The format in the plural, for lists: "scene files".
  std::string_view plural;
  /// The file name extensions, dot included; the first is the one written.
  std::span<const std::string_view> extensions;
  /// How a file in this format starts, for the unknown-format hint:
  /// "a CAMERA record".
  std::string_view startsWith;
  /// Bytes, not text: never written to a terminal.
  bool binary = false;
  /// A file with one of `extensions` whose content no format recognises is
  /// read as this format (POV-Ray, whose language has no signature).
  bool readsUnrecognisedByExtension = false;
  /// What the format holds.
  FormatHolds holds;
  /// Whether `bytes` are in this format.
  Recognition (*recognise)(std::string_view bytes) = nullptr;
  /// The reader: parseSceneAs with this format.
  ReadResult (*read)(std::string_view text, std::string fileName,
                     const ReadOptions& options) = nullptr;
  /// The writer: convertSceneToFiles with this format, after the scene's
  /// numbers have been checked.
  std::optional<ConvertedFiles> (*write)(const Scene& scene, const ConversionOptions& options,
                                         DiagnosticList& out) = nullptr;
  /// An editor's view of a line format's text (scenefile/outline.h,
  /// scenefile/layout.h): outlineOf, placeAt and canonicalLayout with this
  /// format. Null for a format with no lines to lay out (glTF, POV-Ray).
  Outline (*outline)(std::string_view text) = nullptr;
  TextPlace (*place)(std::string_view text, std::size_t lineStart, std::uint32_t line,
                     std::uint32_t column) = nullptr;
  std::optional<std::string> (*layout)(std::string_view text) = nullptr;
};

/// Every format, in the order of scenefile/formats.def.
std::span<const FormatInfo> formats();

/// The row of `format`.
const FormatInfo& formatInfo(Format format);

/// The format named `name` (FormatInfo::name), if any.
const FormatInfo* findFormatByName(std::string_view name);

/// The format whose extensions hold the extension of `fileName` ("a/b.gltf"
/// gives glTF), if any. Extensions compare exactly, case included.
const FormatInfo* findFormatByExtension(std::string_view fileName);

/// The formats for a help text: "scene files (.sf), instruction files
/// (.txt), glTF 2.0 (.gltf), binary glTF 2.0 (.glb) and POV-Ray scenes
/// (.pov)".
std::string describeFormats();

/// The formats' names joined with ", ": "sf, instructions, gltf, glb, pov".
std::string formatNames();

}  // namespace scene
