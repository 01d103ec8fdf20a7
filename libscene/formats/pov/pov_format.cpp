// POV-Ray's row of the format registry.
#include <string_view>

#include "libscene/formats/format_rows.h"
#include "libscene/formats/pov/pov_reader.h"
#include "libscene/formats/pov/pov_writer.h"
#include "scenefile/convert.h"

namespace scene {
namespace {

constexpr std::string_view kPovExtensions[] = {".pov"};

Recognition recognisePov(std::string_view text) {
  return looksLikePov(text) ? Recognition::Certain : Recognition::None;
}

ReadResult readPovFormat(std::string_view text, std::string fileName, const ReadOptions& options) {
  return importPov(text, std::move(fileName), options).read;
}

std::optional<ConvertedFiles> writePovFormat(const Scene& scene, const ConversionOptions& options,
                                             DiagnosticList& out) {
  std::optional<std::string> text = writePovScene(scene, options, out);
  if (!text) return std::nullopt;
  return ConvertedFiles{std::move(*text), {}};
}

}  // namespace

FormatInfo povFormat() {
  FormatInfo row;
  row.format = Format::Pov;
  row.name = "pov";
  row.singular = "a POV-Ray scene";
  row.plural = "POV-Ray scenes";
  row.extensions = kPovExtensions;
  row.startsWith = "a directive such as #version or a statement such as camera {";
  // The language has no signature: a .pov that says nothing else is one.
  row.readsUnrecognisedByExtension = true;
  // Materials and the view are written exactly (with exact-value
  // comments for what the syntax cannot hold) and read back.
  row.holds = {.materials = true, .transformLists = true, .outputFile = true, .view = true};
  row.recognise = recognisePov;
  row.read = readPovFormat;
  row.write = writePovFormat;
  return row;
}

}  // namespace scene
