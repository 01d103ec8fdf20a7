// Diagnostics: what the library reports about an input, as values.
//
// The library collects diagnostics and never prints or exits; the tools decide
// how to show them (text in the compiler's form, or JSON). Every kind of
// problem has a stable code, listed in one table in docs/DIAGNOSTICS.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

enum class Severity : std::uint8_t { Note, Warning, Error };

std::string_view severityName(Severity severity);

// A place in a source file. Lines and columns count from 1; columns count
// bytes. A span of length 0 points between two characters (the end of a line).
struct SourceSpan {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::uint32_t length = 0;

  bool known() const { return line != 0; }
  friend bool operator==(const SourceSpan&, const SourceSpan&) = default;
};

// Stable codes: the names in docs/DIAGNOSTICS.md. Append new codes; never
// rename or reuse one, since users filter on them.
enum class DiagnosticCode : std::uint16_t {
  // Text and numbers.
  InvalidByte,
  InvalidNumber,
  NumberOutOfRange,
  CommentNotAllowed,
  UnknownKeyword,
  TokenCount,
  UnknownFormat,
  // Scene file structure.
  MissingCamera,
  CameraNotFirst,
  DuplicateCamera,
  TruncatedRecord,
  BlankLineInRecord,
  ExpectedRecordName,
  // Values.
  MatrixLastRow,
  MatrixSingular,
  MatrixIllConditioned,
  NegativeColour,
  ColourAboveOne,
  CameraDegenerate,
  CameraScaled,
  NoLight,
  ValueOutOfRange,
  RiBelowOne,
  ZeroScale,
  // Instruction file structure.
  MissingOutputFile,
  OutputFileName,
  OutputFileEscapes,
  UnexpectedLine,
  UnclosedBlock,
  MismatchedEnd,
  UnexpectedEnd,
  DuplicateProperty,
  MissingProperty,
  DuplicateSection,
  UnknownObjectKind,
  CameraLookAtLocation,
  // Conversion.
  LossMaterial,
  LossCameraRoll,
  MatrixNotExpressible,
  MatrixApproximated,
  CameraRollApproximated,
  DroppedOutputFile,
  IgnoredLightMatrix,
  TooManyErrors,
  // glTF: writing.
  PlaneMadeFinite,
  LightFalloff,
  GltfValueClamped,
  GltfExtrasOnly,
  GltfMatrixSplit,
  // glTF: reading.
  GltfInvalidJson,
  GltfInvalidGlb,
  GltfInvalid,
  GltfIndexOutOfRange,
  GltfBadAccessor,
  GltfExternalFile,
  GltfNodeCycle,
  GltfUnsupportedExtension,
  GltfTooLarge,
  GltfMeshNotPrimitive,
  GltfMeshFit,
  GltfLightApproximated,
  GltfExtraCamera,
  GltfNoCamera,
  CameraFov,
  GltfIgnored,
  GltfExtrasStale,
  // POV-Ray: writing.
  LossPov,
  // POV-Ray: reading.
  PovSyntax,
  PovUnsupported,
  PovRefused,
  PovLimit,
  PovUnknownIdentifier,
  PovIgnored,
  PovLoss,
  PovDegenerate,
  // Limits on what one input may cost (ReadOptions).
  FileTooLarge,
  TooManyObjects,
  // Numbers: a value that is not finite once evaluated, composed or converted.
  ValueNotFinite,
  // glTF: more objects than ReadOptions::maxGltfNodes.
  GltfTooManyNodes,
  // OUTPUT_FILE: no image format sfrender writes; a loop of symbolic links.
  OutputFileFormat,
  OutputFileLinkLoop,
};

// Every code, in declaration order: for documentation and coverage tests.
const std::vector<DiagnosticCode>& allDiagnosticCodes();

// The stable kebab-case name of a code, as printed in brackets.
std::string_view codeName(DiagnosticCode code);

// A replacement the user (or an editor) can apply to fix the problem.
struct FixIt {
  SourceSpan span;
  std::string replacement;
  friend bool operator==(const FixIt&, const FixIt&) = default;
};

// A secondary location that explains a diagnostic ("block opened here").
struct DiagnosticNote {
  SourceSpan span;
  std::string message;
  friend bool operator==(const DiagnosticNote&, const DiagnosticNote&) = default;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  DiagnosticCode code = DiagnosticCode::UnknownFormat;
  std::string file;
  SourceSpan span;
  // Lower case, no final period, as in clang.
  std::string message;
  // One line of advice printed after the message, or empty.
  std::string hint;
  std::vector<DiagnosticNote> notes;
  std::optional<FixIt> fixIt;

  friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

// Collects the diagnostics of one operation, in the order they were found.
// After `errorLimit` errors the list takes no more and says so once, so that a
// file of garbage costs bounded memory; readers stop when `full()`.
class DiagnosticList {
 public:
  static constexpr std::size_t kDefaultErrorLimit = 1000;

  explicit DiagnosticList(std::string file = {}, std::size_t errorLimit = kDefaultErrorLimit)
      : file_(std::move(file)), errorLimit_(errorLimit) {}

  const std::string& file() const { return file_; }

  Diagnostic& report(Severity severity, DiagnosticCode code, SourceSpan span, std::string message);
  Diagnostic& error(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Error, code, span, std::move(message));
  }
  Diagnostic& warning(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Warning, code, span, std::move(message));
  }
  Diagnostic& note(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Note, code, span, std::move(message));
  }

  void append(const DiagnosticList& other);

  bool full() const { return errorCount_ >= errorLimit_; }
  bool hasErrors() const { return errorCount_ != 0; }
  std::size_t errorCount() const { return errorCount_; }
  std::size_t warningCount() const { return warningCount_; }
  const std::vector<Diagnostic>& items() const { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  std::string file_;
  std::vector<Diagnostic> items_;
  std::size_t errorLimit_;
  std::size_t errorCount_ = 0;
  std::size_t warningCount_ = 0;
  Diagnostic discarded_;  // what report() returns once the list is full
};

}  // namespace scene
