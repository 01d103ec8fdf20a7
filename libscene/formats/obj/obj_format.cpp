// Wavefront OBJ's row of the format registry: the .obj, with its materials
// in an MTL file beside it.
#include <array>
#include <filesystem>
#include <string_view>

#include "libscene/formats/format_rows.h"
#include "libscene/formats/obj/obj_reader.h"
#include "libscene/formats/obj/obj_writer.h"
#include "libscene/text/text_lines.h"
#include "scenefile/convert.h"

namespace scene {
namespace {

constexpr std::string_view kObjExtensions[] = {".obj"};
// The comments hold every value of the scene (obj_exact.h).
constexpr FormatHolds kHolds{
    .materials = true, .transformLists = true, .outputFile = true, .view = true};
// The statements an OBJ file starts with.
constexpr std::array<std::string_view, 11> kStatements = {"v", "vn", "vt",     "vp",     "f", "o",
                                                          "g", "s",  "mtllib", "usemtl", "l"};

// OBJ has no signature: a first statement of its own is Likely, and a file
// of comments alone is left to the extension (readsUnrecognisedByExtension).
Recognition recogniseObj(std::string_view text) {
  std::optional<std::string_view> first = firstWordOutsideComments(text);
  if (!first) return Recognition::None;
  for (std::string_view statement : kStatements) {
    if (*first == statement) return Recognition::Likely;
  }
  return Recognition::None;
}

// The MTL files are looked for in the file's own folder.
ReadResult readObjFormat(std::string_view text, std::string fileName, const ReadOptions& options) {
  std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
  return parseObj(text, std::move(fileName), folder, options);
}

std::optional<ConvertedFiles> writeObjFormat(const Scene& scene, const ConversionOptions& options,
                                             DiagnosticList& out) {
  return writeObj(scene, options, out);
}

}  // namespace

FormatInfo objFormat() {
  FormatInfo row;
  row.format = Format::Obj;
  row.name = "obj";
  row.singular = "a Wavefront OBJ file";
  row.plural = "Wavefront OBJ";
  row.extensions = kObjExtensions;
  row.startsWith = "a 'v', 'f', 'o' or 'mtllib' statement";
  row.readsUnrecognisedByExtension = true;
  row.holds = kHolds;
  row.recognise = recogniseObj;
  row.read = readObjFormat;
  row.write = writeObjFormat;
  return row;
}

}  // namespace scene
