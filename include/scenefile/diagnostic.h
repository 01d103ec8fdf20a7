/// @file
/// Diagnostics: what the library reports about an input, as values.
///
/// The library collects diagnostics and never prints or exits; the tools decide
/// how to show them (text in the compiler's form, or JSON). Every kind of
/// problem has a stable code, listed in one table in docs/DIAGNOSTICS.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

enum class Severity : std::uint8_t { Note, Warning, Error };

std::string_view severityName(Severity severity);

/// A place in a source file. Lines and columns count from 1; columns count
/// bytes. A span of length 0 points between two characters (the end of a line).
struct SourceSpan {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::uint32_t length = 0;

  bool known() const { return line != 0; }
  friend bool operator==(const SourceSpan&, const SourceSpan&) = default;
};

/// A stable code for each kind of problem, printed by its name (codeName).
/// The codes are listed once, in diagnostic_codes.def, and documented in
/// docs/DIAGNOSTICS.md; new ones are appended there, so that no value
/// changes, and a renamed one keeps its old name as an alias.
enum class DiagnosticCode : std::uint16_t {
#define SCENEFILE_DIAGNOSTIC(enumerator, name) enumerator,
#include "scenefile/diagnostic_codes.def"
};

/// Every code, in declaration order: for documentation and coverage tests.
const std::vector<DiagnosticCode>& allDiagnosticCodes();

/// The stable kebab-case name of a code, as printed in brackets; "unknown"
/// for a value that is no code.
std::string_view codeName(DiagnosticCode code);

/// The code with the name `name` as codeName prints it, or as it was before
/// a rename (docs/DIAGNOSTICS.md, "Renamed codes"), so that a filter written
/// for an older version still finds it; nothing for any other text. Exact
/// and case-sensitive.
std::optional<DiagnosticCode> diagnosticCodeFromName(std::string_view name);

/// A replacement the user (or an editor) can apply to fix the problem.
struct FixIt {
  SourceSpan span;
  std::string replacement;
  friend bool operator==(const FixIt&, const FixIt&) = default;
};

/// A secondary location that explains a diagnostic ("block opened here").
struct DiagnosticNote {
  SourceSpan span;
  std::string message;
  friend bool operator==(const DiagnosticNote&, const DiagnosticNote&) = default;
};

/// A setting a user can change: a limit or option of the library's
/// (ReadOptions, ConversionOptions) or one of a render's. The library names
/// it as data and never in words, since each front end calls it differently:
/// a tool by its flag, Python by its keyword, the Blender add-on by its
/// option (docs/DIAGNOSTICS.md, "Remedies").
enum class Setting : std::uint8_t {
  MaxFileSize,         ///< ReadOptions::maxFileSize
  MaxObjects,          ///< ReadOptions::maxObjects
  MaxGltfNodes,        ///< GltfReadOptions::maxNodes
  TransposedMatrices,  ///< SceneFileReadOptions::transposedMatrices
  SkipUnsupported,     ///< PovReadOptions::skipUnsupported
  Approximate,         ///< InstructionWriteOptions::approximate
  FieldOfView,         ///< a render's vertical field of view, in degrees
  Width,               ///< a render's image width, in pixels
  Height,              ///< a render's image height, in pixels
  Depth,               ///< a render's bounces
  OutputPath,          ///< where a render's image is written
};

/// The stable kebab-case name of a setting ("max-file-size"), for data
/// such as Python's Remedy; "unknown" for a value that is no setting.
std::string_view settingName(Setting setting);

/// A setting that would cure a diagnostic, and the value that would do.
struct Remedy {
  Setting setting = Setting::MaxFileSize;
  /// The value as text ("50"); "true" for an option to turn on; empty
  /// where the advice is only which setting to change.
  std::string value;
  friend bool operator==(const Remedy&, const Remedy&) = default;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  DiagnosticCode code = DiagnosticCode::UnknownFormat;
  std::string file;
  SourceSpan span;
  /// Lower case, no final period, as in clang.
  std::string message;
  /// One line of advice printed after the message, or empty. "{0}", "{1}",
  /// ... stand for remedies[0], [1], ... in the front end's words (hintText).
  std::string hint;
  std::vector<DiagnosticNote> notes;
  std::optional<FixIt> fixIt;
  std::vector<Remedy> remedies;

  friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

/// `hint` with each "{N}" that has a remedies[N] replaced by
/// `words(remedies[N])`: how a front end says a hint in its own terms.
template <typename Words>
std::string hintText(std::string_view hint, const std::vector<Remedy>& remedies, Words&& words) {
  std::string out;
  for (std::size_t i = 0; i < hint.size(); ++i) {
    std::size_t n = i + 2 < hint.size() && hint[i] == '{' && hint[i + 2] == '}'
                        ? static_cast<std::size_t>(hint[i + 1] - '0')
                        : remedies.size();
    if (n < remedies.size()) {
      out += words(remedies[n]);
      i += 2;
    } else {
      out += hint[i];
    }
  }
  return out;
}

/// Collects the diagnostics of one operation, in the order they were found.
/// After `errorLimit` errors the list takes no more and says so once, so that a
/// file of garbage costs bounded memory; readers stop when `full()`.
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
