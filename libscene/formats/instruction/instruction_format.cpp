// The instruction file's row of the format registry.
#include <string_view>

#include "libscene/formats/format_rows.h"
#include "libscene/formats/instruction/instruction_layout.h"
#include "libscene/formats/instruction/instruction_outline.h"
#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/formats/instruction/instruction_writer.h"
#include "libscene/text/text_lines.h"
#include "scenefile/convert.h"
#include "scenefile/outline.h"

namespace scene {
namespace {

constexpr std::string_view kInstructionExtensions[] = {".txt"};

// An instruction file starts with OUTPUT_FILE (or, missing it, START); a
// misspelt one is still recognised, so that its reader can say what is wrong.
Recognition recogniseInstructionFile(std::string_view text) {
  std::optional<std::string_view> first = firstWordOutsideComments(text);
  if (!first) return Recognition::None;
  if (*first == "OUTPUT_FILE" || *first == "START" || *first == "END" ||
      startsWithIgnoringCase(*first, "OUTPUT") || startsWithIgnoringCase(*first, "START")) {
    return Recognition::Likely;
  }
  return Recognition::None;
}

std::optional<ConvertedFiles> writeInstructionFileFormat(const Scene& scene,
                                                         const ConversionOptions& options,
                                                         DiagnosticList& out) {
  std::optional<std::string> text = writeInstructionFile(scene, options, out);
  if (!text) return std::nullopt;
  return ConvertedFiles{std::move(*text), {}};
}

ReadResult readInstructionFileFormat(std::string_view text, std::string fileName,
                                     const ReadOptions& options) {
  return parseInstructionFile(text, std::move(fileName), options);
}

}  // namespace

FormatInfo instructionFileFormat() {
  FormatInfo row;
  row.format = Format::InstructionFile;
  row.name = "instructions";
  row.singular = "an instruction file";
  row.plural = "instruction files";
  row.extensions = kInstructionExtensions;
  row.startsWith = "OUTPUT_FILE";
  row.holds = {.materials = true, .transformLists = true, .outputFile = true};
  row.recognise = recogniseInstructionFile;
  row.read = readInstructionFileFormat;
  row.outline = instructionFileOutline;
  row.place = instructionFilePlace;
  row.layout = instructionFileLayout;
  row.write = writeInstructionFileFormat;
  return row;
}

}  // namespace scene
